namespace QuantumRayTracing.Rendering;

/// <summary>
/// The configuration `render` uses unless told otherwise, and the reference every render is compared
/// with. The defaults are the measured best (docs/rendering-results.md).
/// </summary>
public static class RenderDefaults
{
    public const bool Neighbours = true;
    public const bool ShadowNeighbours = true;
    public const StopMode Stop = StopMode.Exact;
    public const int LatticeLevels = 4;
    public const double AgreedMiss = 0.4;
    public static readonly double? PlannedMiss = null;

    /// <summary>The classical render of the same image: strict ties, no pipeline tricks (it needs none: its answers are certain).</summary>
    public static RenderOptions Reference(RenderOptions options) =>
        options with { TieBreak = Intersection.TieBreak.Strict, Neighbours = false, ShadowNeighbours = false, Stop = StopMode.Off, LatticeLevels = 0 };
}
