using QuantumRayTracing.Output;
using QuantumRayTracing.Passes;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// A finished render: the image, each pass's metrics in order, and their total; <see cref="Radiance"/>
/// holds each pixel's linear value before display encoding.
/// </summary>
public sealed record RenderResult(RgbImage Image, IReadOnlyList<PassMetrics> Passes)
{
    public IReadOnlyList<Scenes.Vec3> Radiance { get; init; } = [];

    /// <summary>The expected wrong pixels the render's searches allow (<see cref="AccuracyBudget"/>).</summary>
    public AccuracyBudget Budget { get; init; } = new(0, 0);

    /// <summary>With estimated light (<see cref="RenderOptions.Light"/>), its error against the exact mean of each point's samples; otherwise null.</summary>
    public Metrics.LightError? LightError { get; init; }

    public PassMetrics Total => PassMetrics.Total("total", Passes.ToArray());
}
