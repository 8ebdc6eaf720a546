using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Shading;

namespace QuantumRayTracing.Passes;

/// <summary>
/// Area lights (the paper's sec. 7): S stratified samples per surface point and light, each a shadow
/// ray whose visibility DirectPass (QOccluded, with every optimisation the options enable) decides;
/// the point receives the sum of its unoccluded samples' radiance · area · cos θ · cos θ' / d² / S.
/// Samples are taken <see cref="SamplesPerChunk"/> indices at a time, so a converged reference with
/// hundreds of samples never holds all its rays at once.
/// </summary>
public static class AreaLightPass
{
    public const string Name = "area shadow";

    public const int SamplesPerChunk = 32;

    /// <summary>The area-light irradiance of each point (all lights, occlusion applied) and the pass's metrics.</summary>
    public static (Vec3[] Irradiance, PassMetrics Metrics) Run(PassPlan plan, IReadOnlyList<SurfacePoint> points, int primaryPoints)
    {
        var irradiance = new Vec3[points.Count];
        var chunks = new List<PassMetrics>();
        var samples = plan.Settings.AreaSamples;
        for (var first = 0; first < samples; first += SamplesPerChunk)
        {
            var connections = Connections(plan.Scene, points, primaryPoints, samples, first, Math.Min(samples, first + SamplesPerChunk), plan.Settings.Seed);
            var rays = connections.Select(c => c.Sample.Ray).ToArray();
            var options = plan.Shadow(connections.Select(c => points[c.Point].Pixel).ToArray(), connections.Select(c => c.Channel).ToArray());
            var (occluded, metrics) = DirectPass.Run(Name, plan.Search, plan.Geometry, rays, options, plan.Progress);
            for (var i = 0; i < connections.Count; i++)
                if (!occluded[i]) irradiance[connections[i].Point] += connections[i].Sample.Irradiance;
            chunks.Add(metrics);
        }
        return (irradiance, PassMetrics.Total(Name, chunks));
    }

    /// <summary>
    /// The shadow samples with indices first..last − 1 of every point and area light: the point each
    /// belongs to and its layout channel (light, sample index, primary or reflected point), so
    /// gathering compares rays to the same stratum of the same light. Samples behind the surface get no ray.
    /// </summary>
    public static List<(int Point, int Channel, ShadowSample Sample)> Connections(
        Scene scene, IReadOnlyList<SurfacePoint> points, int primaryPoints, int count, int first, int last, ulong seed)
    {
        var connections = new List<(int, int, ShadowSample)>();
        for (var k = 0; k < points.Count; k++)
        {
            var kind = k < primaryPoints ? 0 : 1;
            for (var a = 0; a < scene.AreaLights.Count; a++)
                for (var s = first; s < last; s++)
                {
                    var light = scene.AreaLights[a];
                    var at = AreaLightSampler.Sample(light, s, count, Stream(seed, points[k].Pixel, kind, a, s));
                    if (SecondaryRays.Towards(points[k], at) is not { } ray) continue;
                    var irradiance = LightIrradiance.AreaSample(points[k].Hit.Point, points[k].Normal, light, at, count);
                    connections.Add((k, ((a * count + s) * 2) + kind, new ShadowSample(ray, irradiance)));
                }
        }
        return connections;
    }

    /// <summary>The stream of sample <paramref name="sample"/> of area light <paramref name="light"/> at a pixel's primary (kind 0) or reflected (1) point.</summary>
    public static SeededRandom Stream(ulong seed, int pixel, int kind, int light, int sample) =>
        SampleStreams.For(seed, RandomStreams.AreaLight, pixel, kind, light, sample);
}
