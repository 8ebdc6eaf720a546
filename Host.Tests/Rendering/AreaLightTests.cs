using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using static QuantumRayTracing.Tests.Intersection.TestScenes;
using static QuantumRayTracing.Tests.Rendering.OnePixelRender;

namespace QuantumRayTracing.Tests.Rendering;

/// <summary>
/// Area lights on 1x1 renders whose one pixel is computed here by hand: a floor point under a 2x2
/// light at height 4, S = 1 and 4 samples placed by the documented rule (stratum of sample s, jitter
/// from the stream keyed by seed, pixel, point, light and sample), the sum
/// Σ L · A · cos θ · cos θ' / d² / S, and occluders that hide all or part of the light.
/// </summary>
public class AreaLightTests
{
    private const ulong Seed = 11;

    // The floor y = 0 (albedo 0.5, 0.6, 0.8), seen from (4, 1, 0) towards (4, 0, 4), below both the light and the occluders.
    private const string Camera = """{ "position": [4, 1, 0], "lookAt": [4, 0, 4], "up": [0, 1, 0] }""";
    private static readonly string Floor = Rect(0, 0, 0, 8, 0, 8);
    private static readonly Vec3 Albedo = new(0.5, 0.6, 0.8);

    // Light x 3..5, z 3..5 at y = 4: area 4, radiance (2, 3, 4).
    private const string Light = "\"areaLights\": [ { \"min\": [3, 4, 3], \"max\": [5, 4, 5], \"radiance\": [2, 3, 4] } ],";
    private static readonly Vec3 Radiance = new(2, 3, 4);

    private static RenderResult Render(Scene scene, int samples, ulong seed = Seed)
    {
        using var search = new ClassicalHitSearch();
        return SceneRenderer.Render(scene, search, new RenderOptions(1, 1, Seed: seed, AreaSamples: samples));
    }

    // Where the one camera ray meets the floor, from the camera's own ray.
    private static Vec3 FloorPoint(Scene scene)
    {
        var ray = CameraRays.For(scene.Camera, 1, 1)[0];
        return ray.At(-ray.Origin.Y / ray.Direction.Y);
    }

    // Sample s of S on the light: S = 1 is one cell, S = 4 a 2x2 grid (x first); jitter (u, v) from the sample's stream.
    private static Vec3 SamplePoint(int s, int count, ulong seed)
    {
        var random = SampleStreams.For(seed, RandomStreams.AreaLight, 0, 0, 0, s);
        var (u, v) = (random.NextDouble(), random.NextDouble());
        var cells = count == 1 ? 1 : 2;
        return new Vec3(3 + 2 * (s % cells + u) / cells, 4, 3 + 2 * (s / cells + v) / cells);
    }

    // L · A · cos θ · cos θ' / d² / S with both cosines h / d: L · A · h² / d⁴ / S.
    private static Vec3 HandSum(Vec3 point, int count, ulong seed, Func<Vec3, bool> visible)
    {
        var sum = Vec3.Zero;
        for (var s = 0; s < count; s++)
        {
            var sample = SamplePoint(s, count, seed);
            if (!visible(sample)) continue;
            var d2 = (sample - point).Dot(sample - point);
            var h = sample.Y - point.Y;
            sum += 4 * h * h / (d2 * d2) / count * Radiance;
        }
        return Albedo * sum;
    }

    [Theory]
    [InlineData(1)]
    [InlineData(4)]
    public void UnoccludedPointGetsTheSumOverItsSamples(int samples)
    {
        var scene = With(4, 0, [Floor], Camera, more: Light);
        var expected = HandSum(FloorPoint(scene), samples, Seed, _ => true);
        AssertClose(expected, Render(scene, samples).Radiance[0]);
    }

    [Fact]
    public void FourSamplesCoverTheFourQuartersOfTheLight()
    {
        var quarters = Enumerable.Range(0, 4).Select(s => SamplePoint(s, 4, Seed)).Select(p => ((int)(p.X - 3), (int)(p.Z - 3))).ToHashSet();
        Assert.Equal(4, quarters.Count);
    }

    [Fact]
    public void AnOccluderOverTheWholeLightLeavesOnlyAmbient()
    {
        var blocked = With(4, 0, [Floor, Rect(2, 2, 2, 6, 2, 6)], Camera, ambient: 0.1, more: Light);
        AssertClose(0.1 * Albedo, Render(blocked, 4).Radiance[0]);
    }

    [Fact]
    public void AnOccluderOverHalfTheLightBlocksExactlyTheSamplesBehindIt()
    {
        // The occluder x 2..4 at y = 2 holds the cells x 2, 3; a sample's segment crosses y = 2 at its midpoint
        // with the floor point (4, 0, 4), x = (4 + x_s) / 2: inside for samples with x_s < 4, the left column.
        var half = With(4, 0, [Floor, Rect(2, 2, 2, 4, 2, 6)], Camera, more: Light);
        var expected = HandSum(FloorPoint(half), 4, Seed, sample => sample.X >= 4);
        var full = HandSum(FloorPoint(half), 4, Seed, _ => true);
        var radiance = Render(half, 4).Radiance[0];
        AssertClose(expected, radiance);
        Assert.InRange(radiance.X, 0.1 * full.X, 0.9 * full.X);
    }

    [Fact]
    public void TheLightItselfShowsPiTimesItsRadiance()
    {
        // Looking straight up at the light, which lies in the plane of a ceiling: the emitter wins the tie.
        var camera = """{ "position": [4, 1, 4], "lookAt": [4, 4, 4], "up": [0, 0, 1] }""";
        var scene = With(4, 0, [Floor, Rect(0, 4, 0, 8, 4, 8)], camera, ambient: 0.5, more: Light);
        AssertClose(Math.PI * Radiance, Render(scene, 4).Radiance[0]);
    }

    [Fact]
    public void SamplesFollowTheSeed()
    {
        var scene = With(4, 0, [Floor], Camera, more: Light);
        var other = Seed + 1;
        AssertClose(HandSum(FloorPoint(scene), 4, other, _ => true), Render(scene, 4, other).Radiance[0]);
        Assert.NotEqual(Render(scene, 4).Radiance[0], Render(scene, 4, other).Radiance[0]);
    }
}
