using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using static QuantumRayTracing.Tests.Intersection.TestScenes;
using static QuantumRayTracing.Tests.Rendering.OnePixelRender;

namespace QuantumRayTracing.Tests.Rendering;

/// <summary>Directional lights on 1x1 renders of a floor point (4, 0, 4), computed by hand: albedo · (ambient + E · cos θ) when nothing blocks the way back to the light.</summary>
public class DirectionalLightTests
{
    private const string Camera = """{ "position": [4, 1, 0], "lookAt": [4, 0, 4], "up": [0, 1, 0] }""";
    private static readonly string Floor = Rect(0, 0, 0, 8, 0, 8);
    private static readonly Vec3 Albedo = new(0.5, 0.6, 0.8);

    private static string Sun(string direction) =>
        $$"""
        "directionalLights": [ { "direction": {{direction}}, "irradiance": [1, 2, 3] } ],
        """;

    [Fact]
    public void VisibleLightGivesIrradianceTimesCosine()
    {
        // Travelling along (3, −4, 0) / 5: the way back makes cos θ = 0.8 with the floor's normal.
        var result = Render(With(4, 0, [Floor], Camera, ambient: 0.1, more: Sun("[3, -4, 0]")));
        AssertClose(Albedo * new Vec3(0.1 + 0.8, 0.1 + 1.6, 0.1 + 2.4), result.Radiance[0]);
        Assert.Equal(1, result.Passes[2].Rays);
    }

    [Fact]
    public void OccluderOnTheWayBackBlocksIt()
    {
        // The way back from (4, 0, 4) along (−0.6, 0.8, 0) crosses y = 2 at x = 2.5, inside the square x 2..3.
        var scene = With(4, 0, [Floor, Rect(2, 2, 3, 3, 2, 5)], Camera, ambient: 0.1, more: Sun("[3, -4, 0]"));
        AssertClose(0.1 * Albedo, Render(scene).Radiance[0]);
    }

    [Fact]
    public void OccluderBesideTheWayBackDoesNot()
    {
        var scene = With(4, 0, [Floor, Rect(5, 2, 3, 6, 2, 5)], Camera, ambient: 0.1, more: Sun("[3, -4, 0]"));
        AssertClose(Albedo * new Vec3(0.1 + 0.8, 0.1 + 1.6, 0.1 + 2.4), Render(scene).Radiance[0]);
    }

    [Fact]
    public void TheShadowRayRunsToTheEdgeOfTheGrid()
    {
        // Straight down: a square at the top of the 4-bit grid (y = 15) still blocks it.
        var scene = With(4, 0, [Floor, Rect(3, 15, 3, 5, 15, 5)], Camera, more: Sun("[0, -1, 0]"));
        AssertClose(Vec3.Zero, Render(scene).Radiance[0]);
    }

    [Fact]
    public void LightFromBehindTheSurfaceGetsNoRay()
    {
        var result = Render(With(4, 0, [Floor], Camera, ambient: 0.1, more: Sun("[0, 1, 0]")));
        AssertClose(0.1 * Albedo, result.Radiance[0]);
        Assert.Equal(0, result.Passes[2].Rays);
    }
}
