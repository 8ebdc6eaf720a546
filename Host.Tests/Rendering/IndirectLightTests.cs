using QuantumRayTracing.Passes;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Rendering;

/// <summary>
/// Single-bounce VPL light by hand: a small floor patch under a large grey ceiling at y = 4 with a point
/// light at (4, 2, 4) between them. Every VPL ray from the floor point goes up to the ceiling (or past
/// its edge, contributing nothing); the VPL there is lit by the point light, so its outgoing value is
/// albedo_ceiling · I · cos θ / d², and the pixel gets albedo_floor · (direct + mean over VPLs).
/// </summary>
public class IndirectLightTests
{
    private const ulong Seed = 5;
    private const string Camera = """{ "position": [4, 1, 0], "lookAt": [4, 0, 4], "up": [0, 1, 0] }""";
    private const string Lamp = """[ { "position": [4, 2, 4], "intensity": [6, 6, 6] } ]""";
    private static readonly Vec3 Intensity = new(6, 6, 6);
    private static readonly Vec3 Albedo = new(0.5, 0.6, 0.8);
    private static readonly Vec3 CeilingAlbedo = new(0.8, 0.8, 0.8);
    private static readonly Scene Room = With(4, 0, [Rect(3, 0, 3, 5, 0, 5), Rect(0, 4, 0, 15, 4, 15, "grey")], Camera, Lamp);

    private static RenderResult Render(int vpls)
    {
        using var search = new ClassicalHitSearch();
        return SceneRenderer.Render(Room, search, new RenderOptions(1, 1, Seed: Seed, Vpl: vpls));
    }

    // VPL v of V: the cell (v mod columns, v div columns) of the 2x2 (V = 4) or 1x1 grid over (φ / 2π, sin²θ),
    // jittered by the first two numbers of the VPL's stream; about the floor's normal +y, tangents x and z.
    private static Vec3 Direction(int v, int count)
    {
        var random = SampleStreams.For(Seed, RandomStreams.Vpl, 0, 0, v);
        var (ju, jv) = (random.NextDouble(), random.NextDouble());
        var cells = count == 1 ? 1 : 2;
        var phi = 2 * Math.PI * (v % cells + ju) / cells;
        var sin2 = (v / cells + jv) / cells;
        var (sin, cos) = (Math.Sqrt(sin2), Math.Sqrt(1 - sin2));
        return new Vec3(sin * Math.Cos(phi), cos, sin * Math.Sin(phi));
    }

    private static Vec3 FloorPoint()
    {
        var camera = CameraRays.For(Room.Camera, 1, 1)[0];
        return camera.At(-camera.Origin.Y / camera.Direction.Y);
    }

    // Where VPL v's ray meets the ceiling's plane, or null past the ceiling's edge (its cells 0..14).
    private static Vec3? Landing(int v, int count)
    {
        var x = FloorPoint();
        var d = Direction(v, count);
        var y = x + (4 - x.Y) / d.Y * d;
        return y.X >= 0 && y.X < 15 && y.Z >= 0 && y.Z < 15 ? y : null;
    }

    private static Vec3 Expected(int count)
    {
        var x = FloorPoint();
        var direct = 2 / Math.Pow((new Vec3(4, 2, 4) - x).Length, 3) * Intensity; // cos θ = 2 / d, light 2 above
        var indirect = Vec3.Zero;
        for (var v = 0; v < count; v++)
        {
            if (Landing(v, count) is not { } y) continue;
            var distance = (new Vec3(4, 2, 4) - y).Length; // the light is 2 below the ceiling: cos θ = 2 / d
            indirect += CeilingAlbedo * (2 / distance / (distance * distance) * Intensity);
        }
        return Albedo * (direct + (1.0 / count) * indirect);
    }

    [Theory]
    [InlineData(1)]
    [InlineData(4)]
    public void OneBounceOffTheCeilingGivesTheHandComputedTerm(int vpls)
    {
        var radiance = Render(vpls).Radiance[0];
        var expected = Expected(vpls);
        Assert.Equal(expected.X, radiance.X, 12);
        Assert.Equal(expected.Y, radiance.Y, 12);
        Assert.Equal(expected.Z, radiance.Z, 12);
    }

    [Fact]
    public void IndirectLightAddsToDirectLight()
    {
        var withVpls = Render(4).Radiance[0];
        var without = Render(0).Radiance[0];
        Assert.True(withVpls.X > without.X * 1.01, $"{withVpls} against {without}");
    }

    [Fact]
    public void EveryPointSendsItsVplsAndEachVplItsShadowRays()
    {
        var result = Render(4);
        var names = result.Passes.Select(p => p.Name).ToArray();
        Assert.Equal(["primary", "specular", "shadow", IndirectPass.TraceName, IndirectPass.ShadowName], names);
        Assert.Equal(4, result.Passes[3].Rays);
        // One point light: one shadow ray per VPL that lands on the ceiling.
        Assert.Equal(Enumerable.Range(0, 4).Count(v => Landing(v, 4) is not null), result.Passes[4].Rays);
    }
}
