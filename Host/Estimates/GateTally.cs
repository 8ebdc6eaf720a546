using System.Text.Json.Nodes;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// One gate list's counts, as the bridge summarises a circuit: gates by kind (named by their
/// controls: CX, CCX, CZ; T† for an adjoint T), measurements and resets (not gates), and the depth:
/// every operation, measurements and resets included, takes one step on each qubit it touches and
/// starts when all of them are free (Qiskit's QuantumCircuit.depth() on the same list).
/// </summary>
public sealed record GateTally(IReadOnlyDictionary<string, long> Gates, long GateCount, long Measurements, long Resets, long Depth)
{
    public long Gate(string kind) => Gates.TryGetValue(kind, out var count) ? count : 0;

    /// <summary>
    /// The tally of a circuit that repeats one body <paramref name="repeats"/> times, from the tallies of
    /// the same circuit with the body once and twice: one + (repeats − 1) · (two − one), every field.
    /// </summary>
    public static GateTally Extrapolate(GateTally one, GateTally two, int repeats)
    {
        long Line(long a, long b) => a + (repeats - 1) * (b - a);
        var kinds = one.Gates.Keys.Union(two.Gates.Keys);
        return new GateTally(kinds.ToDictionary(k => k, k => Math.Max(0, Line(one.Gate(k), two.Gate(k)))),
            Line(one.GateCount, two.GateCount), Line(one.Measurements, two.Measurements), Line(one.Resets, two.Resets), Line(one.Depth, two.Depth));
    }

    public static GateTally Parse(JsonNode tally)
    {
        var gates = (tally["gates"] ?? throw new FormatException("a gate tally has no gates")).AsObject()
            .ToDictionary(p => p.Key, p => p.Value!.GetValue<long>());
        return new GateTally(gates, tally["gateCount"]!.GetValue<long>(), tally["measurements"]!.GetValue<long>(),
            tally["resets"]!.GetValue<long>(), tally["depth"]!.GetValue<long>());
    }
}
