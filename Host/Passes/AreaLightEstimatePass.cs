using QuantumRayTracing.Estimation;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Metrics;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using QuantumRayTracing.Shading;

namespace QuantumRayTracing.Passes;

/// <summary>
/// Area light estimated as a mean (docs/rendering.md, *Quantum light estimation*): each surface point and area light has the
/// fixed set of S = 2^k samples <see cref="AreaLightPass"/> would trace. Sample s has the weight g_s = area · cos θ · cos θ' / d²
/// (0 behind the surface) and the visibility v_s of its shadow ray; the point's irradiance is L_e · mean_s(g_s v_s). With the
/// bound B = max_s g_s, the values F_s = g_s v_s / B lie in [0, 1], and the estimator reads their mean f with Q queries:
/// irradiance L_e · B · f̂. The exact mean B · f is kept beside it for <see cref="LightError"/>.
/// </summary>
/// <remarks>
/// The analytic coin engine needs the true amplitude, so every sample's visibility is computed here classically (N tests
/// per sample, as the classical engine does): the simulation's work, in neither #Eval nor #C_Int. One query is one coherent
/// evaluation of a sample's weight and visibility over all N primitives (a coin flip 1, a Grover operator 2); the pass's rays
/// are the shadow rays its queries replace, so its Int/Ray is queries per replaced shadow ray.
/// </remarks>
public static class AreaLightEstimatePass
{
    /// <summary>Items per estimator call, in a fixed order: the draws, and so the image, depend only on the seed.</summary>
    public const int BlockItems = 2048;

    public static (Vec3[] Irradiance, LightError Error, PassMetrics Metrics) Run(PassPlan plan, IReadOnlyList<SurfacePoint> points, int primaryPoints, LightEstimation light)
    {
        var clock = System.Diagnostics.Stopwatch.StartNew();
        var (scene, options) = (plan.Scene, plan.Settings);
        var samples = options.AreaSamples;
        var lights = scene.AreaLights.Count;
        var sets = new SampleSet?[points.Count * lights];
        Parallel.For(0, points.Count, k =>
        {
            for (var a = 0; a < lights; a++) sets[k * lights + a] = SetOf(scene, plan.Geometry, points[k], k < primaryPoints ? 0 : 1, a, samples, options.Seed);
        });

        var root = new SeededRandom(options.Seed).Fork(RandomStreams.LightEstimation);
        var estimator = light.CreateEstimator(root.Fork(0));
        var engine = new QueryCountingEngine(new AnalyticCoinEngine(root.Fork(1)));
        var items = Enumerable.Range(0, sets.Length).Where(i => sets[i] is { Bound: > 0 }).ToArray();
        var means = new double[sets.Length];
        for (var start = 0; start < items.Length; start += BlockItems)
        {
            var block = items.AsSpan(start, Math.Min(BlockItems, items.Length - start)).ToArray();
            var estimates = estimator.Estimate(block.Select(i => sets[i]!.Values).ToArray(), engine);
            for (var j = 0; j < block.Length; j++) means[block[j]] = estimates[j];
            plan.Progress?.Report(Name(light), (double)(start + block.Length) / items.Length);
        }

        var irradiance = new Vec3[points.Count];
        var exact = new Vec3[points.Count];
        for (var i = 0; i < sets.Length; i++)
        {
            if (sets[i] is not { Bound: > 0 } set) continue;
            var radiance = scene.AreaLights[i % lights].Radiance;
            irradiance[i / lights] += set.Bound * means[i] * radiance;
            exact[i / lights] += set.Bound * set.Values.Average() * radiance;
        }
        var error = LightError.None;
        for (var k = 0; k < points.Count; k++)
            error = error.Add(irradiance[k].X, exact[k].X).Add(irradiance[k].Y, exact[k].Y).Add(irradiance[k].Z, exact[k].Z);

        // Monte Carlo draws without the coin engine: one query per draw.
        var queries = estimator is SampleMeanEstimator ? estimator.Queries * items.Length : engine.Queries;
        var rays = sets.Sum(s => (long)(s?.Rays ?? 0));
        var metrics = new PassMetrics(Name(light), rays, 0, new SearchCost(queries, queries, 0, 0), 0, clock.Elapsed);
        return (irradiance, error, metrics);
    }

    public static string Name(LightEstimation light) => $"area light {light.Name}";

    /// <summary>
    /// One point's sample set for area light <paramref name="a"/>: the samples <see cref="AreaLightPass.Connections"/> takes (the
    /// same streams), each sample's value g_s v_s / B, the bound B and the shadow rays the set stands for.
    /// </summary>
    private static SampleSet SetOf(Scene scene, SceneGeometry geometry, SurfacePoint point, int kind, int a, int count, ulong seed)
    {
        var light = scene.AreaLights[a];
        var weights = new double[count];
        var rays = 0;
        // The bound is the largest weight, visible or not: what the coin's rotation is scaled by needs no visibility.
        var bound = 0.0;
        for (var s = 0; s < count; s++)
        {
            var at = AreaLightSampler.Sample(light, s, count, AreaLightPass.Stream(seed, point.Pixel, kind, a, s));
            if (SecondaryRays.Towards(point, at) is not { } ray) continue;
            rays++;
            var weight = LightIrradiance.AreaGeometry(point.Hit.Point, point.Normal, light, at);
            bound = Math.Max(bound, weight);
            var table = RayTable.BuildCompact(geometry, ray);
            if (table.BestAccepted(table.FullRange) is null) weights[s] = weight;
        }
        return new SampleSet(bound > 0 ? weights.Select(w => Math.Clamp(w / bound, 0, 1)).ToArray() : weights, bound, rays);
    }

    /// <summary>A point's samples of one light: values in [0, 1], the bound they were scaled by, and the shadow rays they stand for.</summary>
    private sealed record SampleSet(double[] Values, double Bound, int Rays);
}
