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
/// mirror, the direct-light pass for every surface point and light, then Whitted shading. Rays are
/// traced breadth first, a whole pass at a time, so each pass batches all its searches. Every engine
/// runs exactly this; they differ only in the <see cref="IHitSearch"/> they bring.
/// </summary>
public static class SceneRenderer
{
    public static RenderResult Render(Scene scene, IHitSearch search, RenderOptions options, IRenderProgress? progress = null)
    {
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
        PassOptions Trace(PixelLayout layout) => new(options.Iterations, options.TieBreak, options.Neighbours ? layout : null, stop, lattice, planned);
        var (primaryHits, primaryMetrics) = TracePass.Run("primary", search, geometry, primaryRays, Trace(PixelLayout.Image(options.Width, options.Height)), progress);

        // Surface points: each primary hit carries 1 − mirror of its pixel, its reflection the mirror share.
        var points = new List<SurfacePoint>();
        var specularPixels = new List<int>();
        var specularRays = new List<Ray>();
        for (var pixel = 0; pixel < primaryRays.Length; pixel++)
        {
            if (primaryHits[pixel] is not { } hit) continue;
            var rectangle = scene.Rectangles[hit.Primitive];
            var point = SurfacePoint.Of(pixel, primaryRays[pixel], hit, rectangle, 1 - rectangle.Material.Mirror);
            if (point.Weight > 0) points.Add(point);
            if (!rectangle.Material.IsMirror) continue;
            specularPixels.Add(pixel);
            specularRays.Add(SecondaryRays.Specular(primaryRays[pixel], point));
        }
        var primaryPointCount = points.Count;
        var (specularHits, specularMetrics) = TracePass.Run("specular", search, geometry, specularRays,
            Trace(new PixelLayout(options.Width, options.Height, specularPixels)), progress);
        for (var k = 0; k < specularRays.Count; k++)
        {
            if (specularHits[k] is not { } hit) continue;
            var mirror = scene.Rectangles[primaryHits[specularPixels[k]]!.Value.Primitive].Material.Mirror;
            // One bounce: a mirror seen in a mirror shows only its diffuse share.
            var rectangle = scene.Rectangles[hit.Primitive];
            points.Add(SurfacePoint.Of(specularPixels[k], specularRays[k], hit, rectangle, mirror * (1 - rectangle.Material.Mirror)));
        }

        // Shadow rays: one per surface point and light in front of it; rayOf[point, light] = −1 for none.
        // Their layout channel is the light and whether the point is primary or reflected, so gathering
        // compares rays towards the same light from the same kind of point.
        var shadowRays = new List<Ray>();
        var shadowPixels = new List<int>();
        var shadowChannels = new List<int>();
        var rayOf = new int[points.Count, scene.Lights.Count];
        for (var k = 0; k < points.Count; k++)
            for (var l = 0; l < scene.Lights.Count; l++)
            {
                var ray = SecondaryRays.Shadow(points[k], scene.Lights[l]);
                rayOf[k, l] = ray is null ? -1 : shadowRays.Count;
                if (ray is null) continue;
                shadowRays.Add(ray);
                shadowPixels.Add(points[k].Pixel);
                shadowChannels.Add(2 * l + (k < primaryPointCount ? 0 : 1));
            }
        var shadowLayout = new PixelLayout(options.Width, options.Height, shadowPixels, shadowChannels);
        var (occluded, shadowMetrics) = DirectPass.Run("shadow", search, geometry, shadowRays,
            new PassOptions(options.ShadowIterations, options.TieBreak, options.ShadowNeighbours ? shadowLayout : null, stop, lattice, planned), progress);

        var radiance = new Vec3[primaryRays.Length];
        for (var k = 0; k < points.Count; k++)
        {
            var point = points[k];
            radiance[point.Pixel] += point.Weight * WhittedShading.Radiance(scene, point, l => rayOf[k, l] >= 0 && !occluded[rayOf[k, l]]);
        }
        var image = RgbImage.FromLinear(options.Width, options.Height, (x, y) =>
        {
            var c = radiance[y * options.Width + x];
            return (WhittedShading.Encode(c.X), WhittedShading.Encode(c.Y), WhittedShading.Encode(c.Z));
        });
        passes.AddRange([primaryMetrics, specularMetrics, shadowMetrics]);
        return new RenderResult(image, passes);
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
        return new StopRule(miss, new SeededRandom(options.Seed).Fork(RandomStreams.Stop));
    }
}
