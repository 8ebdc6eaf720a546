using System.Diagnostics;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Metrics;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Benchmarks;

/// <summary>
/// One measured render: what it cost (its metrics and wall time) and how far it is from the classical
/// render of the same scene and options.
/// </summary>
public sealed record RenderMeasurement(RenderResult Result, ImageError Error, TimeSpan WallTime)
{
    public double MillisecondsPerRay => WallTime.TotalMilliseconds / Math.Max(1, Result.Total.Rays);

    /// <summary>
    /// Renders <paramref name="scene"/> on <paramref name="kind"/> and compares it with <paramref name="reference"/>;
    /// a Q# engine runs on <paramref name="pool"/> when given (a cluster's bridges), else on bridges of its own.
    /// </summary>
    public static RenderMeasurement Run(Scene scene, EngineKind kind, RenderOptions options, QSearchOptions qsearch, ulong seed, int workers, RenderMeasurement? reference, Noise.NoiseModel? noise = null, Bridge.BridgePool? pool = null)
    {
        var clock = Stopwatch.StartNew();
        RenderResult result;
        using (var search = HitSearchFactory.Create(kind, new SeededRandom(seed), workers, qsearch, pool: pool, noise: noise))
            result = SceneRenderer.Render(scene, search, options);
        var wall = clock.Elapsed;
        var error = reference is null ? default : ImageError.Between(result.Image, reference.Result.Image);
        return new RenderMeasurement(result, error, wall);
    }

    /// <summary>The classical render every other render of these options is compared with.</summary>
    public static RenderMeasurement Reference(Scene scene, RenderOptions options) =>
        Run(scene, EngineKind.Classical, RenderDefaults.Reference(options), new QSearchOptions(), 0, 1, null);
}
