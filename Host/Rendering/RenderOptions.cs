using QuantumRayTracing.Intersection;
using QuantumRayTracing.Passes;

namespace QuantumRayTracing.Rendering;

/// <summary>What a render does beyond the scene: image size, TracePass iterations (#IT) for primary and specular rays, DirectPass rounds, tie-breaking.</summary>
public sealed record RenderOptions(
    int Width,
    int Height,
    int Iterations = RenderOptions.DefaultIterations,
    int ShadowIterations = DirectPass.DefaultIterations,
    TieBreak TieBreak = TieBreak.Strict)
{
    /// <summary>The paper's table 3 reaches its floor of wrong pixels on the Qornell box at 4 to 5 passes.</summary>
    public const int DefaultIterations = 4;
}
