using QuantumRayTracing.Intersection;
using QuantumRayTracing.Passes;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// What a render does beyond the scene: image size, TracePass iterations (#IT) for primary and
/// specular rays, DirectPass rounds, tie-breaking, neighbour gathering (NeighOpt for primary and
/// specular rays, occluder gathering for shadow rays), the termination criterion and the seed of its draws.
/// </summary>
public sealed record RenderOptions(
    int Width,
    int Height,
    int Iterations = RenderOptions.DefaultIterations,
    int ShadowIterations = DirectPass.DefaultIterations,
    TieBreak TieBreak = TieBreak.Strict,
    bool Neighbours = false,
    bool ShadowNeighbours = false,
    StopMode Stop = StopMode.Off,
    ulong Seed = 1)
{
    /// <summary>The paper's table 3 reaches its floor of wrong pixels on the Qornell box at 4 to 5 passes.</summary>
    public const int DefaultIterations = 4;
}
