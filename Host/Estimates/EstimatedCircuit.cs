using QuantumRayTracing.Intersection;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// One circuit the estimates cover: its name in tables, what it is, the Q# call that applies it to
/// fresh registers, and the registers this program models for it (null when there is no model).
/// </summary>
public sealed record EstimatedCircuit(
    string Name,
    string Description,
    Func<EstimateSubject, string> Expression,
    Func<EstimateSubject, OracleRegisters?> Registers)
{
    public override string ToString() => Name;
}
