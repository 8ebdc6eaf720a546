using QuantumRayTracing.Intersection;
using QuantumRayTracing.Metrics;
using QuantumRayTracing.Output;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using QuantumRayTracing.Shading;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// RenderScene (appendix B, Algorithm 7) as stages over queues of typed work: rays are traced breadth first, a
/// whole pass at a time, so each pass batches all its searches. Every engine runs exactly this; they differ only
/// in the <see cref="IHitSearch"/> they bring. <see cref="Renderer"/> is the way in.
/// </summary>
public static class SceneRenderer
{
    /// <param name="scene">The scene.</param>
    /// <param name="search">The engine's search.</param>
    /// <param name="options">The render's options; a window's size.</param>
    /// <param name="progress">Told how far each pass is.</param>
    /// <param name="window">The image's pixels to render (a tile, <see cref="TiledRender"/>), options.Width x options.Height of them; null: the whole image.</param>
    public static RenderResult Render(Scene scene, IHitSearch search, RenderOptions options, IRenderProgress? progress = null, ImageWindow? window = null)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(options.AreaSamples, 1);
        ArgumentOutOfRangeException.ThrowIfNegative(options.Vpl);
        if (window is { } w && (w.Width != options.Width || w.Height != options.Height))
            throw new ArgumentException($"a {w.Width}x{w.Height} window rendered at {options.Width}x{options.Height}", nameof(window));
        // Stages in order: camera rays, the pass plan (its stop rule may calibrate on camera rays), primary rays,
        // specular rays, shadow rays, area light, indirect light, shading. Each pass's metrics are kept in that order.
        var passes = new List<PassMetrics>();
        // Camera and shadow rays are computed from their pixel or surface point when read, never all held (docs/rendering.md).
        var cameraRays = CameraRays.Computed(scene.Camera, window ?? ImageWindow.Whole(options.Width, options.Height));
        var plan = PlanPasses(scene, search, options, cameraRays, passes, progress);
        var pixels = cameraRays.Count;
        var radiance = WrittenArray.Of<Vec3>(pixels);
        var allowed = (options.Budget ?? 0) * pixels;
        var (primaryPoints, specularQueue) = TracePrimaryRays(plan, cameraRays, radiance, passes, allowed / 2);
        var points = TraceSpecularRays(plan, primaryPoints, specularQueue, radiance, passes, Left(allowed, passes) / 3);
        var visible = TraceShadowRays(plan, points, passes, Left(allowed, passes));
        var budgeted = passes.ToArray();
        var extra = DirectionalLight(scene, points, visible);
        var lightError = AddAreaLight(plan, points, extra, passes);
        AddIndirectLight(plan, points, extra, passes);
        Shade(scene, points, visible, extra, radiance);
        return Result(plan, radiance, passes, AccuracyBudget.From(budgeted, pixels, options.Budget)) with { LightError = lightError };
    }

    // The expected wrong rays of the passes so far: the budget left is what they did not spend (none, when a pass
    // ended over its allowance).
    private static double Left(double allowed, List<PassMetrics> passes) => Math.Max(0, allowed - passes.Sum(p => p.PlannedWrong));

    // The optimisations every pass shares: the planned schedule, the stop rule and the lattice plan.
    private static PassPlan PlanPasses(Scene scene, IHitSearch search, RenderOptions options, IReadOnlyList<Ray> cameraRays, List<PassMetrics> passes, IRenderProgress? progress)
    {
        var geometry = new SceneGeometry(scene);
        var planned = options.PlannedMiss is { } miss
            ? ConfirmationPlanner.Cheapest(geometry.Count, ConfirmationPlanner.MaxT, miss)
            : null;
        var stop = StopRuleFor(search, geometry, cameraRays, options, planned, passes);
        var lattice = options.LatticeLevels > 0
            ? new LatticePlan(options.LatticeLevels, ConfirmationPlanner.Cheapest(geometry.Count, ConfirmationPlanner.MaxT, options.AgreedMiss),
                options.SizeConfirmation)
            : null;
        return new PassPlan(scene, geometry, search, options.ForPasses(), stop, lattice, planned, progress);
    }

    // Camera rays to their closest hits. Each hit is a surface point carrying 1 − mirror of its pixel; a mirror's
    // reflection, queued for the specular pass, carries the mirror share. A ray that meets an area light first shows the light.
    private static (List<SurfacePoint> Points, List<SpecularRayWorkItem> Specular) TracePrimaryRays(PassPlan plan, IReadOnlyList<Ray> cameraRays, Vec3[] radiance, List<PassMetrics> passes,
        double allowance)
    {
        var (hits, metrics) = TracePass.Run("primary", plan.Search, plan.Geometry, cameraRays,
            plan.Trace(Enumerable.Range(0, cameraRays.Count).ToArray(), allowance: allowance), plan.Progress);
        passes.Add(metrics);
        var points = new List<SurfacePoint>(cameraRays.Count);
        var specular = new List<SpecularRayWorkItem>();
        InOrder.Run(cameraRays.Count, pixel =>
        {
            var ray = cameraRays[pixel];
            if (SeenLight(plan.Scene, ray, hits[pixel]) is { } light) return new HitResult(light, null, null);
            if (hits[pixel] is not { } hit) return default;
            var material = plan.Scene.Primitives[hit.Primitive].Material;
            var point = SurfacePoint.Of(pixel, ray, hit, plan.Scene.Primitives[hit.Primitive], 1 - material.Mirror);
            return new HitResult(null, point, material.IsMirror ? new(pixel, material.Mirror, SecondaryRays.Specular(ray, point)) : null);
        }, (pixel, result) =>
        {
            if (result.Light is { } light) radiance[pixel] = light;
            if (result.Point is { Weight: > 0 } point) points.Add(point);
            if (result.Reflection is { } reflection) specular.Add(reflection);
        });
        return (points, specular);
    }

    // What a camera or mirror ray's hit gives its pixel: an area light's exitance, or a surface point (and, on a mirror, its reflection).
    private readonly record struct HitResult(Vec3? Light, SurfacePoint? Point, SpecularRayWorkItem? Reflection);

    // Mirror reflections to their closest hits: one bounce, so a mirror seen in a mirror shows only its diffuse share.
    private static SurfacePoints TraceSpecularRays(PassPlan plan, List<SurfacePoint> points, List<SpecularRayWorkItem> queue, Vec3[] radiance, List<PassMetrics> passes,
        double allowance)
    {
        var primaryCount = points.Count;
        var rays = queue.Select(w => w.Ray).ToArray();
        var (hits, metrics) = TracePass.Run("specular", plan.Search, plan.Geometry, rays, plan.Trace(queue.Select(w => w.Pixel).ToArray(), allowance: allowance), plan.Progress);
        passes.Add(metrics);
        // Room for the reflected points at once: growing by doubling would hold up to twice the points.
        points.Capacity = Math.Max(points.Capacity, points.Count + queue.Count);
        InOrder.Run(queue.Count, k =>
        {
            var (pixel, mirror, ray) = queue[k];
            if (SeenLight(plan.Scene, ray, hits[k]) is { } light) return new HitResult(mirror * light, null, null);
            if (hits[k] is not { } hit) return default;
            var primitive = plan.Scene.Primitives[hit.Primitive];
            return new HitResult(null, SurfacePoint.Of(pixel, ray, hit, primitive, mirror * (1 - primitive.Material.Mirror)), null);
        }, (k, result) =>
        {
            if (result.Light is { } light) radiance[queue[k].Pixel] += light;
            if (result.Point is { } point) points.Add(point);
        });
        return new SurfacePoints(points, primaryCount);
    }

    // The area light a camera or mirror ray meets before its hit, if any.
    private static Vec3? SeenLight(Scene scene, Ray ray, Hit? hit) =>
        scene.AreaLights.Count > 0 ? Emitters.Seen(ray, hit?.Distance ?? double.PositiveInfinity, scene.AreaLights) : null;

    // One shadow ray per surface point and point or directional light in front of it; visible[point, light] after the pass.
    private static bool[,] TraceShadowRays(PassPlan plan, SurfacePoints points, List<PassMetrics> passes, double allowance)
    {
        var scene = plan.Scene;
        var lightCount = scene.Lights.Count + scene.DirectionalLights.Count;
        // Which (point, light) pairs have a ray, on all cores and without building it; then the work items, in point-major order.
        var present = new bool[points.Count * lightCount];
        Parallel.For(0, points.Count, k =>
        {
            for (var l = 0; l < lightCount; l++) present[k * lightCount + l] = ShadowRayWorkItem.Exists(scene, points, k, l);
        });
        var items = new ShadowRayWorkItem[present.AsSpan().Count(true)];
        for (int k = 0, i = 0; k < points.Count; k++)
            for (var l = 0; l < lightCount; l++)
                if (present[k * lightCount + l]) items[i++] = new ShadowRayWorkItem(k, l);
        var rays = new ComputedList<Ray>(items.Length, i => items[i].Ray(scene, points));
        var pixels = new ComputedList<int>(items.Length, i => items[i].Pixel(points));
        var channels = new ComputedList<int>(items.Length, i => items[i].Channel(points));
        var (occluded, metrics) = DirectPass.Run("shadow", plan.Search, plan.Geometry, rays, plan.Shadow(pixels, channels, allowance: allowance), plan.Progress);
        passes.Add(metrics);
        var visible = new bool[points.Count, lightCount];
        for (var i = 0; i < items.Length; i++) visible[items[i].Point, items[i].Light] = !occluded[i];
        return visible;
    }

    // Irradiance beyond Whitted's point lights, per point: first the directional lights the shadow pass found unoccluded.
    private static Vec3[] DirectionalLight(Scene scene, SurfacePoints points, bool[,] visible)
    {
        var extra = new Vec3[points.Count];
        var pointLights = scene.Lights.Count;
        for (var k = 0; k < points.Count; k++)
            for (var d = 0; d < scene.DirectionalLights.Count; d++)
                if (visible[k, pointLights + d]) extra[k] += LightIrradiance.Directional(points[k].Normal, scene.DirectionalLights[d]);
        return extra;
    }

    // Every sample's shadow ray traced, or (with a light estimator) the mean over each point's samples estimated; the latter's
    // error against the exact mean is returned.
    private static LightError? AddAreaLight(PassPlan plan, SurfacePoints points, Vec3[] extra, List<PassMetrics> passes)
    {
        if (plan.Scene.AreaLights.Count == 0) return plan.Settings.Light is null ? null : LightError.None;
        var (area, error, metrics) = plan.Settings.Light is { } light
            ? AreaLightEstimatePass.Run(plan, points.Points, points.PrimaryCount, light)
            : AreaLightPass.Run(plan, points.Points, points.PrimaryCount) is var (traced, tracedMetrics) ? (traced, (LightError?)null, tracedMetrics) : default;
        for (var k = 0; k < points.Count; k++) extra[k] += area[k];
        passes.Add(metrics);
        return error;
    }

    private static void AddIndirectLight(PassPlan plan, SurfacePoints points, Vec3[] extra, List<PassMetrics> passes)
    {
        if (plan.Settings.Vpl == 0) return;
        var (indirect, traceMetrics, shadowMetrics) = IndirectPass.Run(plan, points.Points, points.PrimaryCount);
        for (var k = 0; k < points.Count; k++) extra[k] += indirect[k];
        passes.AddRange([traceMetrics, shadowMetrics]);
    }

    // Whitted shading of every point with the lights it sees, plus the extra irradiance on its diffuse colour; a pixel
    // adds its points in order (its primary point first).
    private static void Shade(Scene scene, SurfacePoints points, bool[,] visible, Vec3[] extra, Vec3[] radiance) =>
        InOrder.Run(points.Count, k =>
        {
            var point = points[k];
            var local = WhittedShading.Radiance(scene, point, l => visible[k, l]);
            if (extra[k] != Vec3.Zero) local += scene.Primitives[point.Hit.Primitive].Material.Diffuse * extra[k];
            return point.Weight * local;
        }, (k, shaded) => radiance[points[k].Pixel] += shaded);

    private static RenderResult Result(PassPlan plan, Vec3[] radiance, List<PassMetrics> passes, AccuracyBudget budget)
    {
        var options = plan.Settings;
        var image = RgbImage.FromLinear(options.Width, options.Height, (x, y) =>
        {
            var c = radiance[y * options.Width + x];
            return (WhittedShading.Encode(c.X), WhittedShading.Encode(c.Y), WhittedShading.Encode(c.Z));
        });
        return new RenderResult(image, passes)
        {
            Radiance = radiance,
            Budget = budget,
        };
    }

    // The termination criterion's rule, or null; Scene mode first measures t on a lattice of primary rays.
    private static StopRule? StopRuleFor(IHitSearch search, SceneGeometry geometry, IReadOnlyList<Ray> primaryRays, RenderOptions options,
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
        // With a budget its rounds search more where the expectation asks, cheaper than a fixed guard on every ray
        // (docs/rendering.md): the paper's one miss. Without one, the guard derived from the budget's target.
        var guard = AccuracyBudget.RequiredMisses(ConfirmationPlanner.WorstMiss(search, geometry.Count, planned), options.Width, options.Height, options.LatticeLevels);
        var required = options.RequiredMisses ?? (options.Budget is not null ? 1 : guard);
        return new StopRule(miss, new SeededRandom(options.Seed).Fork(RandomStreams.Stop), required, options.Budget is not null ? guard : null);
    }
}
