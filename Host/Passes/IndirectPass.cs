using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Shading;

namespace QuantumRayTracing.Passes;

/// <summary>
/// Single-bounce indirect light from virtual point lights (the paper's sec. 7, fig. 14). From every
/// surface point x, V stratified cosine-weighted directions are traced with TracePass (closest hit: the "vpl"
/// pass); each hit y is a VPL, whose own direct light from every light of the scene (one shadow ray per
/// point or directional light, one area-light sample per area light) DirectPass decides ("vpl shadow").
/// A VPL's outgoing value is B(y) = albedo_y · E_direct(y), in the renderer's units (no 1/π, as in
/// direct shading), and x receives the indirect irradiance mean over its VPLs of B(y): with directions
/// of density cos θ / π, ∫ B(y)/π · cos θ dω is estimated by exactly that mean. A ray that finds nothing
/// contributes zero. VPLs are taken <see cref="VplsPerChunk"/> indices at a time to bound memory.
/// </summary>
public static class IndirectPass
{
    public const string TraceName = "vpl";
    public const string ShadowName = "vpl shadow";

    public const int VplsPerChunk = 16;

    public static (Vec3[] Irradiance, PassMetrics Trace, PassMetrics Shadow) Run(PassPlan plan, IReadOnlyList<SurfacePoint> points, int primaryPoints)
    {
        var (scene, options) = (plan.Scene, plan.Settings);
        var vpls = options.Vpl;
        var sum = new Vec3[points.Count];
        var (traces, shadows) = (new List<PassMetrics>(), new List<PassMetrics>());
        for (var first = 0; first < vpls; first += VplsPerChunk)
        {
            var last = Math.Min(vpls, first + VplsPerChunk);
            var owners = new List<(int Point, int Vpl)>();
            var rays = new List<Ray>();
            var channels = new List<int>();
            for (var k = 0; k < points.Count; k++)
                for (var v = first; v < last; v++)
                {
                    var kind = Kind(k, primaryPoints);
                    var direction = CosineHemisphere.Direction(points[k].Normal, v, vpls, SampleStreams.For(options.Seed, RandomStreams.Vpl, points[k].Pixel, kind, v));
                    owners.Add((k, v));
                    rays.Add(SecondaryRays.Bounce(points[k], direction));
                    channels.Add(v * 2 + kind);
                }
            var traceOptions = plan.Trace(owners.Select(o => points[o.Point].Pixel).ToArray(), channels);
            var (hits, traceMetrics) = TracePass.Run(TraceName, plan.Search, plan.Geometry, rays, traceOptions, plan.Progress);
            traces.Add(traceMetrics);

            // Each VPL's direct light: one shadow sample per light, channel (VPL, light, kind).
            var lights = LightCount(scene);
            var connections = new List<(int Ray, int Channel, ShadowSample Sample)>();
            for (var i = 0; i < rays.Count; i++)
            {
                if (hits[i] is not { } hit) continue;
                var (k, v) = owners[i];
                var vpl = SurfacePoint.Of(points[k].Pixel, rays[i], hit, scene.Primitives[hit.Primitive], 1);
                foreach (var (light, sample) in DirectSamples(scene, vpl, options.Seed, Kind(k, primaryPoints), v))
                    connections.Add((i, (v * lights + light) * 2 + Kind(k, primaryPoints), sample));
            }
            // No termination here: neighbouring pixels' VPLs lie far apart, so gathering rarely repairs a
            // missed occluder, and one wrongly lit VPL adds a whole light sample to its pixel.
            var shadowOptions = plan.Shadow(connections.Select(c => points[owners[c.Ray].Point].Pixel).ToArray(), connections.Select(c => c.Channel).ToArray(), terminate: false);
            var (occluded, shadowMetrics) = DirectPass.Run(ShadowName, plan.Search, plan.Geometry, connections.Select(c => c.Sample.Ray).ToArray(),
                shadowOptions, plan.Progress);
            shadows.Add(shadowMetrics);
            for (var j = 0; j < connections.Count; j++)
            {
                if (occluded[j]) continue;
                var ray = connections[j].Ray;
                var albedo = scene.Primitives[hits[ray]!.Value.Primitive].Material.Diffuse;
                sum[owners[ray].Point] += albedo * connections[j].Sample.Irradiance;
            }
        }
        var irradiance = sum.Select(b => (1.0 / vpls) * b).ToArray();
        return (irradiance, PassMetrics.Total(TraceName, traces), PassMetrics.Total(ShadowName, shadows));
    }

    /// <summary>
    /// The direct light of a VPL at <paramref name="vpl"/>: (light index, sample) for every light in
    /// front of it — point lights, then directional lights, then one sample of each area light drawn
    /// from the stream keyed by pixel, point kind, VPL and light.
    /// </summary>
    public static IEnumerable<(int Light, ShadowSample Sample)> DirectSamples(Scene scene, SurfacePoint vpl, ulong seed, int kind, int index)
    {
        var at = vpl.Hit.Point;
        for (var l = 0; l < scene.Lights.Count; l++)
            if (SecondaryRays.Shadow(vpl, scene.Lights[l]) is { } ray)
                yield return (l, new ShadowSample(ray, LightIrradiance.Point(at, vpl.Normal, scene.Lights[l])));
        var offset = scene.Lights.Count;
        for (var d = 0; d < scene.DirectionalLights.Count; d++)
            if (SecondaryRays.TowardsDirectional(vpl, scene.DirectionalLights[d], scene.Grid) is { } ray)
                yield return (offset + d, new ShadowSample(ray, LightIrradiance.Directional(vpl.Normal, scene.DirectionalLights[d])));
        offset += scene.DirectionalLights.Count;
        for (var a = 0; a < scene.AreaLights.Count; a++)
        {
            var light = scene.AreaLights[a];
            var sample = AreaLightSampler.Sample(light, 0, 1, SampleStreams.For(seed, RandomStreams.VplAreaLight, vpl.Pixel, kind, index, a));
            if (SecondaryRays.Towards(vpl, sample) is { } ray)
                yield return (offset + a, new ShadowSample(ray, LightIrradiance.AreaSample(at, vpl.Normal, light, sample, 1)));
        }
    }

    private static int LightCount(Scene scene) => scene.Lights.Count + scene.DirectionalLights.Count + scene.AreaLights.Count;

    private static int Kind(int point, int primaryPoints) => point < primaryPoints ? 0 : 1;
}
