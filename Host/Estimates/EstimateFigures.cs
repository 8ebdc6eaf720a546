using QuantumRayTracing.Intersection;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// What `estimate` prints, for its --json file: the table exactly as printed, and each circuit's estimate as
/// numbers (the records the table's cells are formatted from).
/// </summary>
public sealed record EstimateFigures(ReportTable Table, IReadOnlyList<EstimateFigures.Circuit> Circuits)
{
    public static EstimateFigures Of(ReportTable table, IEnumerable<CircuitEstimate> estimates) =>
        new(table, estimates.Select(e => new Circuit(e.Circuit.Name, e.Subject.Iterations, e.Logical, e.Physical, e.Counts, e.Registers)).ToArray());

    /// <summary>One circuit: the estimator's logical counts, its physical figures per qubit model, the extracted circuit's counts, the modelled registers.</summary>
    public sealed record Circuit(string Name, int Iterations, LogicalCounts Logical, IReadOnlyList<PhysicalEstimate> Physical, CircuitCounts? Counts, OracleRegisters? Registers);
}
