using QuantumRayTracing.Output;
using QuantumRayTracing.Passes;

namespace QuantumRayTracing.Rendering;

/// <summary>A finished render: the image, each pass's metrics in order, and their total.</summary>
public sealed record RenderResult(RgbImage Image, IReadOnlyList<PassMetrics> Passes)
{
    public PassMetrics Total => PassMetrics.Total("total", Passes.ToArray());
}
