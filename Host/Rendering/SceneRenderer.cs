using QuantumRayTracing.Intersection;
using QuantumRayTracing.Output;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using QuantumRayTracing.Shading;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// RenderScene (appendix B, Algorithm 7): the primary pass, the specular pass for pixels that see a
/// mirror, the direct-light pass for every surface point and point or directional light, then Whitted
/// shading; with area lights an area-light pass, and with VPLs the indirect passes (sec. 7). Rays are
/// traced breadth first, a whole pass at a time, so each pass batches all its searches. Every engine
/// runs exactly this; they differ only in the <see cref="IHitSearch"/> they bring.
/// </summary>
public static class SceneRenderer
{
    public static RenderResult Render(Scene scene, IHitSearch search, RenderOptions options, IRenderProgress? progress = null)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(options.AreaSamples, 1);
        ArgumentOutOfRangeException.ThrowIfNegative(options.Vpl);
        var geometry = new SceneGeometry(scene);
        var primaryRays = CameraRays.For(scene.Camera, options.Width, options.Height);
        var passes = new List<PassMetrics>();
        var planned = options.PlannedMiss is { } miss
            ? ConfirmationPlanner.Cheapest(geometry.Count, RenderOptions.ConfirmationMaxT, miss)
            : null;
        var stop = StopRuleFor(search, geometry, primaryRays, options, planned, passes);
        var lattice = options.LatticeLevels > 0
            ? new LatticePlan(options.LatticeLevels, ConfirmationPlanner.Cheapest(geometry.Count, RenderOptions.ConfirmationMaxT, options.AgreedMiss))
            : null;
        var plan = new PassPlan(scene, geometry, search, options, stop, lattice, planned, progress);
        var (primaryHits, primaryMetrics) = TracePass.Run("primary", search, geometry, primaryRays, plan.Trace(Enumerable.Range(0, primaryRays.Length).ToArray()), progress);

        // Surface points: each primary hit carries 1 − mirror of its pixel, its reflection the mirror share.
        // A camera or mirror ray that meets an area light before its hit shows the light instead.
        var radiance = new Vec3[primaryRays.Length];
        var points = new List<SurfacePoint>();
        var specularPixels = new List<int>();
        var specularRays = new List<Ray>();
        for (var pixel = 0; pixel < primaryRays.Length; pixel++)
        {
            var hit = primaryHits[pixel];
            if (scene.AreaLights.Count > 0 && Emitters.Seen(primaryRays[pixel], hit?.Distance ?? double.PositiveInfinity, scene.AreaLights) is { } light)
            {
                radiance[pixel] = light;
                continue;
            }
            if (hit is not { } h) continue;
            var rectangle = scene.Rectangles[h.Primitive];
            var point = SurfacePoint.Of(pixel, primaryRays[pixel], h, rectangle, 1 - rectangle.Material.Mirror);
            if (point.Weight > 0) points.Add(point);
            if (!rectangle.Material.IsMirror) continue;
            specularPixels.Add(pixel);
            specularRays.Add(SecondaryRays.Specular(primaryRays[pixel], point));
        }
        var primaryPointCount = points.Count;
        var (specularHits, specularMetrics) = TracePass.Run("specular", search, geometry, specularRays,
            plan.Trace(specularPixels), progress);
        for (var k = 0; k < specularRays.Count; k++)
        {
            var pixel = specularPixels[k];
            var mirror = scene.Rectangles[primaryHits[pixel]!.Value.Primitive].Material.Mirror;
            var hit = specularHits[k];
            if (scene.AreaLights.Count > 0 && Emitters.Seen(specularRays[k], hit?.Distance ?? double.PositiveInfinity, scene.AreaLights) is { } light)
            {
                radiance[pixel] += mirror * light;
                continue;
            }
            if (hit is not { } h) continue;
            // One bounce: a mirror seen in a mirror shows only its diffuse share.
            var rectangle = scene.Rectangles[h.Primitive];
            points.Add(SurfacePoint.Of(pixel, specularRays[k], h, rectangle, mirror * (1 - rectangle.Material.Mirror)));
        }

        // Shadow rays: one per surface point and point or directional light in front of it (lights
        // 0..P−1 are the point lights, P.. the directional ones); rayOf[point, light] = −1 for none.
        // Their layout channel is the light and whether the point is primary or reflected, so gathering
        // compares rays towards the same light from the same kind of point.
        var pointLights = scene.Lights.Count;
        var lightCount = pointLights + scene.DirectionalLights.Count;
        var shadowRays = new List<Ray>();
        var shadowPixels = new List<int>();
        var shadowChannels = new List<int>();
        var rayOf = new int[points.Count, lightCount];
        for (var k = 0; k < points.Count; k++)
            for (var l = 0; l < lightCount; l++)
            {
                var ray = l < pointLights
                    ? SecondaryRays.Shadow(points[k], scene.Lights[l])
                    : SecondaryRays.TowardsDirectional(points[k], scene.DirectionalLights[l - pointLights], scene.Grid);
                rayOf[k, l] = ray is null ? -1 : shadowRays.Count;
                if (ray is null) continue;
                shadowRays.Add(ray);
                shadowPixels.Add(points[k].Pixel);
                shadowChannels.Add(2 * l + (k < primaryPointCount ? 0 : 1));
            }
        var (occluded, shadowMetrics) = DirectPass.Run("shadow", search, geometry, shadowRays,
            plan.Shadow(shadowPixels, shadowChannels), progress);
        passes.AddRange([primaryMetrics, specularMetrics, shadowMetrics]);
        bool Visible(int k, int l) => rayOf[k, l] >= 0 && !occluded[rayOf[k, l]];

        // Irradiance beyond Whitted's point lights: directional, area and indirect light, per point.
        var extra = new Vec3[points.Count];
        for (var k = 0; k < points.Count; k++)
            for (var d = 0; d < scene.DirectionalLights.Count; d++)
                if (Visible(k, pointLights + d)) extra[k] += LightIrradiance.Directional(points[k].Normal, scene.DirectionalLights[d]);
        if (scene.AreaLights.Count > 0)
        {
            var (area, areaMetrics) = AreaLightPass.Run(plan, points, primaryPointCount);
            for (var k = 0; k < points.Count; k++) extra[k] += area[k];
            passes.Add(areaMetrics);
        }
        if (options.Vpl > 0)
        {
            var (indirect, traceMetrics, vplShadowMetrics) = IndirectPass.Run(plan, points, primaryPointCount);
            for (var k = 0; k < points.Count; k++) extra[k] += indirect[k];
            passes.AddRange([traceMetrics, vplShadowMetrics]);
        }

        for (var k = 0; k < points.Count; k++)
        {
            var point = points[k];
            var local = WhittedShading.Radiance(scene, point, l => Visible(k, l));
            if (extra[k] != Vec3.Zero) local += scene.Rectangles[point.Hit.Primitive].Material.Diffuse * extra[k];
            radiance[point.Pixel] += point.Weight * local;
        }
        var image = RgbImage.FromLinear(options.Width, options.Height, (x, y) =>
        {
            var c = radiance[y * options.Width + x];
            return (WhittedShading.Encode(c.X), WhittedShading.Encode(c.Y), WhittedShading.Encode(c.Z));
        });
        return new RenderResult(image, passes)
        {
            Radiance = radiance,
            Budget = AccuracyBudget.From(passes, search, geometry.Count, lattice?.Agreed, stop?.RequiredMisses ?? 1, primaryRays.Length),
        };
    }

    // The termination criterion's rule, or null; Scene mode first measures t on a lattice of primary rays.
    private static StopRule? StopRuleFor(IHitSearch search, SceneGeometry geometry, Ray[] primaryRays, RenderOptions options,
        QSearchSchedule? planned, List<PassMetrics> passes)
    {
        if (options.Stop == StopMode.Off) return null;
        var pt = FalseNegativeRate.Uniform(geometry.Count, geometry.Count);
        if (options.Stop == StopMode.Scene)
        {
            (pt, var calibration) = SceneTDistribution.Measure(geometry, primaryRays, options.Width, options.Height);
            passes.Add(calibration);
        }
        var miss = search.MissProbability(geometry.Count, pt, paperFormula: options.Stop == StopMode.Paper, planned);
        var required = options.RequiredMisses ?? AccuracyBudget.RequiredMisses(
            AccuracyBudget.WorstMiss(search, geometry.Count, planned), options.Width, options.Height, options.LatticeLevels);
        return new StopRule(miss, new SeededRandom(options.Seed).Fork(RandomStreams.Stop), required);
    }
}
