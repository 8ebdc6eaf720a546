using System.Text.Json.Nodes;
using QuantumRayTracing.Bridge;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// The Resource Estimator's logical counts of a Q# program (its <c>logicalCounts</c>): peak qubits in
/// use, T gates, single-qubit rotations, CCZ and CCiX gates (the QDK's Toffoli-class primitives; an
/// AND computed into a fresh qubit counts as a CCZ, its measurement-based uncomputation as a
/// measurement), and measurements.
/// </summary>
public sealed record LogicalCounts(int Qubits, long T, long Rotations, long RotationDepth, long Ccz, long Ccix, long Measurements)
{
    /// <summary>
    /// The counts of a circuit that repeats one body <paramref name="repeats"/> times (a QSearch run's r
    /// iterations), from those with the body once and twice: one + (repeats − 1) · (two − one), each
    /// count; the width is the wider one's. Exact, as every repetition is the same circuit.
    /// </summary>
    public static LogicalCounts Extrapolate(LogicalCounts one, LogicalCounts two, int repeats)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(repeats, 1);
        long Line(long a, long b) => a + (repeats - 1) * (b - a);
        return new LogicalCounts(Math.Max(one.Qubits, two.Qubits), Line(one.T, two.T), Line(one.Rotations, two.Rotations),
            Line(one.RotationDepth, two.RotationDepth), Line(one.Ccz, two.Ccz), Line(one.Ccix, two.Ccix), Line(one.Measurements, two.Measurements));
    }

    /// <summary>
    /// The Q# call the estimator prices these counts through (Estimation.AccountForLogicalCounts). It
    /// takes no CCiX count: circuits with CCiX gates are refused rather than priced as something else.
    /// </summary>
    public string AccountingExpression => Ccix == 0
        ? FormattableString.Invariant($"{QSharpOperations.AccountForLogicalCounts}({Qubits}, {T}, {Rotations}, {RotationDepth}, {Ccz}, {Measurements})")
        : throw new NotSupportedException($"counts with {Ccix} CCiX gates cannot be priced from counts alone");

    public static LogicalCounts Parse(JsonNode estimate)
    {
        var counts = estimate["logicalCounts"] ?? throw new FormatException($"the estimator's result has no logicalCounts: {estimate.ToJsonString()}");
        long Count(string name) => counts[name]?.GetValue<long>() ?? throw new FormatException($"logicalCounts has no {name}");
        return new LogicalCounts((int)Count("numQubits"), Count("tCount"), Count("rotationCount"), Count("rotationDepth"),
            Count("cczCount"), Count("ccixCount"), Count("measurementCount"));
    }
}
