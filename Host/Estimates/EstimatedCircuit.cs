using QuantumRayTracing.Intersection;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// One circuit the estimates cover: its name in tables, what it is, the Q# call that applies it to
/// fresh registers, the registers this program models for it (null when there is no model), and
/// whether it repeats one body <see cref="EstimateSubject.Iterations"/> times (then its circuit can be
/// extrapolated from the runs with one and two repetitions, <see cref="CircuitCounts.Extrapolate"/>).
/// </summary>
public sealed record EstimatedCircuit(
    string Name,
    string Description,
    Func<EstimateSubject, string> Expression,
    Func<EstimateSubject, OracleRegisters?> Registers,
    bool RepeatsIterations = false)
{
    public override string ToString() => Name;
}
