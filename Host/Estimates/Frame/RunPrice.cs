namespace QuantumRayTracing.Estimates;

/// <summary>
/// What one Grover run of a given shape and r costs: the Resource Estimator's logical counts, and its
/// physical figures on every qubit model with the run's share of the frame budget
/// (<see cref="Split"/>) and with the whole frame budget to itself (<see cref="Alone"/>), in the
/// order of the models.
/// </summary>
public sealed record RunPrice(LogicalCounts Logical, IReadOnlyList<PhysicalEstimate> Split, IReadOnlyList<PhysicalEstimate> Alone);
