using System.Diagnostics;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Metrics;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// One measured render: what it cost (its metrics and wall time) and how far it is from the classical
/// render of the same scene and options.
/// </summary>
public sealed record RenderMeasurement(RenderResult Result, ImageError Error, TimeSpan WallTime)
{
    public double MillisecondsPerRay => WallTime.TotalMilliseconds / Math.Max(1, Result.Total.Rays);

    /// <summary>
    /// Renders <paramref name="scene"/> on <paramref name="engine"/> with <paramref name="options"/> (their seed included)
    /// and compares it with <paramref name="reference"/>.
    /// </summary>
    public static RenderMeasurement Run(Scene scene, EngineSetup engine, RenderOptions options, RenderMeasurement? reference)
    {
        var clock = Stopwatch.StartNew();
        var result = Renderer.Render(scene, engine, options);
        var wall = clock.Elapsed;
        var error = reference is null ? default : ImageError.Between(result.Image, reference.Result.Image);
        return new RenderMeasurement(result, error, wall);
    }

    /// <summary>The classical render every other render of these options is compared with.</summary>
    public static RenderMeasurement Reference(Scene scene, RenderOptions options) =>
        Run(scene, new EngineSetup(EngineKind.Classical), RenderDefaults.Reference(options), null);
}
