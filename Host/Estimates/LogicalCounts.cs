using System.Text.Json.Nodes;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// The Resource Estimator's logical counts of a Q# program (its <c>logicalCounts</c>): peak qubits in
/// use, T gates, single-qubit rotations, CCZ and CCiX gates (the QDK's Toffoli-class primitives; an
/// AND computed into a fresh qubit counts as a CCZ, its measurement-based uncomputation as a
/// measurement), and measurements.
/// </summary>
public sealed record LogicalCounts(int Qubits, long T, long Rotations, long RotationDepth, long Ccz, long Ccix, long Measurements)
{
    public static LogicalCounts Parse(JsonNode estimate)
    {
        var counts = estimate["logicalCounts"] ?? throw new FormatException($"the estimator's result has no logicalCounts: {estimate.ToJsonString()}");
        long Count(string name) => counts[name]?.GetValue<long>() ?? throw new FormatException($"logicalCounts has no {name}");
        return new LogicalCounts((int)Count("numQubits"), Count("tCount"), Count("rotationCount"), Count("rotationDepth"),
            Count("cczCount"), Count("ccixCount"), Count("measurementCount"));
    }
}
