using System.Text.Json.Nodes;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// The circuit the QDK extracts from a Q# program (getCircuit, the trace of one simulated run), as the
/// bridge summarises it: in the QDK's own intrinsic gate set (<see cref="Native"/>: X, H, CX, CCX, CZ,
/// rotations, …) and with every CCX replaced by Qiskit's 15-gate definition of ccx (2 H, 6 CX, 4 T,
/// 3 T†; <see cref="QiskitCcx"/>), the basis in which Qiskit reports a Toffoli circuit.
/// </summary>
/// <remarks>
/// The standard library uncomputes ANDs and lookups by measuring and then applying Z or CZ
/// corrections only on some outcomes, so the Z and CZ counts and the depth are those of the run that
/// was traced and vary a little between runs; every other count is fixed by the program.
/// </remarks>
public sealed record CircuitCounts(int Qubits, long Operations, GateTally Native, GateTally QiskitCcx)
{
    /// <summary>Whether the counts were extrapolated from shorter runs (<see cref="Extrapolate"/>) rather than traced.</summary>
    public bool Extrapolated { get; init; }

    /// <summary>
    /// The counts of a circuit that applies one body <paramref name="repeats"/> times (a QSearch run's r
    /// iterations), from the traced circuits with the body once and twice. Exact for every count but the
    /// outcome-dependent corrections, since each repetition is the same circuit; the depth is exact when
    /// each repetition adds the same depth, as serial iterations on the same registers do.
    /// </summary>
    public static CircuitCounts Extrapolate(CircuitCounts one, CircuitCounts two, int repeats) =>
        new(Math.Max(one.Qubits, two.Qubits), one.Operations + (repeats - 1) * (two.Operations - one.Operations),
            GateTally.Extrapolate(one.Native, two.Native, repeats), GateTally.Extrapolate(one.QiskitCcx, two.QiskitCcx, repeats))
        { Extrapolated = true };

    /// <summary>Gate kinds whose count depends on measurement outcomes (the uncomputations' phase corrections).</summary>
    public static readonly IReadOnlySet<string> OutcomeDependentKinds = new HashSet<string> { "Z", "CZ" };

    public static CircuitCounts Parse(JsonNode summary) => new(
        summary["qubits"]!.GetValue<int>(),
        summary["operations"]!.GetValue<long>(),
        GateTally.Parse(summary["native"]!),
        GateTally.Parse(summary["qiskitCcx"]!));
}
