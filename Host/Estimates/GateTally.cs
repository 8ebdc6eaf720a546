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

    public static GateTally Parse(JsonNode tally)
    {
        var gates = (tally["gates"] ?? throw new FormatException("a gate tally has no gates")).AsObject()
            .ToDictionary(p => p.Key, p => p.Value!.GetValue<long>());
        return new GateTally(gates, tally["gateCount"]!.GetValue<long>(), tally["measurements"]!.GetValue<long>(),
            tally["resets"]!.GetValue<long>(), tally["depth"]!.GetValue<long>());
    }
}
