using QuantumRayTracing.Intersection;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// Everything measured about one circuit for one subject: the estimator's logical counts and physical
/// figures per qubit model, the extracted circuit's counts (null when not asked for), and the
/// registers this program models for it.
/// </summary>
public sealed record CircuitEstimate(
    EstimatedCircuit Circuit,
    EstimateSubject Subject,
    LogicalCounts Logical,
    IReadOnlyList<PhysicalEstimate> Physical,
    CircuitCounts? Counts,
    OracleRegisters? Registers);
