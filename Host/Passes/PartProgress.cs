namespace QuantumRayTracing.Passes;

/// <summary>
/// Progress of one part of a stage: the part's 0..1 maps onto [start, start + share] of the whole,
/// so a pass run in several parts (lattice levels) reports one rising figure instead of restarting.
/// </summary>
public sealed class PartProgress(IRenderProgress inner, double start, double share) : IRenderProgress
{
    public void Report(string stage, double done) => inner.Report(stage, start + share * Math.Clamp(done, 0, 1));
}
