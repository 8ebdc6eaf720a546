using System.Numerics;
using System.Text.Json.Nodes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Noise;

/// <summary>
/// Noise locations of a circuit: one per qubit per operation, measurements included, since the QDK's
/// noisy simulator applies its Pauli channel to every qubit an operation touches (a CCX is three
/// locations, a measurement one). The lookup oracle's Grover run is counted in closed form from the
/// circuit <c>MeasureGroverSearch</c> builds (tested against the circuits the bridge extracts); any
/// other circuit is counted from the bridge's circuit summary.
/// </summary>
public static class NoiseLocations
{
    /// <summary>
    /// Locations of a Grover run outside its iterations: the preparation and the index measurement. Exact when N is a power of two; otherwise the preparation's controlled
    /// rotations are counted as the plain H gates of the next power of two (an undercount).
    /// </summary>
    public static long PrepareAndMeasure(int count)
    {
        var n = SearchRegisters.For(count).IndexQubits;
        return n + n;
    }

    /// <summary>
    /// Locations of one lookup-oracle Grover iteration over <paramref name="marked"/>: per oracle index the
    /// X gates that move the index register to all ones and one phase on the all-ones state; then the diffusion
    /// (unprepare, X on every index qubit, the phase on all ones, undo). The oracle marks the complement
    /// when more than half is marked, as the Q# operation does. Exact for N a power of two.
    /// </summary>
    public static long LookupIteration(MarkedSet marked)
    {
        ArgumentNullException.ThrowIfNull(marked);
        var n = SearchRegisters.For(marked.Count).IndexQubits;
        var complement = 2 * marked.MarkedCount > marked.Count;
        var oracleSize = complement ? marked.Count - marked.MarkedCount : marked.MarkedCount;
        var diffusion = 2L * n + 2L * n + PhaseToAllOnes(n);
        return diffusion + oracleSize * PhaseToAllOnes(n) + Toggles(marked, complement, n);
    }

    /// <summary>
    /// Locations of the phase on the all-ones state of n index qubits (<c>ApplyPhaseToAllOnes</c>): none for
    /// n = 0 (a global phase), Z (1) for n = 1, CZ (2) for n = 2, and for n ≥ 3 the Toffoli ladder and its
    /// undoing, 2(n − 2) CCX (3 each), around one CZ (2).
    /// </summary>
    public static long PhaseToAllOnes(int n) => n <= 0 ? 0 : n == 1 ? 1 : n == 2 ? 2 : 6L * (n - 2) + 2;

    // X gates moving the index register from one oracle index's all-ones pattern to the next, and back.
    private static long Toggles(MarkedSet marked, bool complement, int n)
    {
        var allOnes = (1 << n) - 1;
        var (total, previous, any) = (0L, 0, false);
        void Visit(int index)
        {
            var flips = allOnes ^ index;
            total += BitOperations.PopCount((uint)(previous ^ flips));
            previous = flips;
            any = true;
        }
        if (complement)
        {
            for (var i = 0; i < marked.Count; i++)
                if (!marked.Contains(i)) Visit(i);
        }
        else
        {
            foreach (var m in marked.Indices) Visit(m);
        }
        return any ? total + BitOperations.PopCount((uint)previous) : 0;
    }

    /// <summary>
    /// Locations of a circuit from the bridge's summary (its <c>native</c> part): each gate kind's count times
    /// the qubits it touches (its controls, named by leading C's, plus its target; SWAP two), plus one per
    /// measurement. Resets are left out: they end a qubit's use.
    /// </summary>
    public static long FromCircuit(JsonObject native)
    {
        ArgumentNullException.ThrowIfNull(native);
        var gates = native["gates"]!.AsObject().ToDictionary(g => g.Key, g => g.Value!.GetValue<long>());
        return FromCounts(gates, native["measurements"]!.GetValue<long>());
    }

    /// <summary>The same count from gate kinds and their counts, as a circuit summary lists them, and the measurements.</summary>
    public static long FromCounts(IReadOnlyDictionary<string, long> gates, long measurements)
    {
        var total = 0L;
        foreach (var (kind, count) in gates) total += count * QubitsOf(kind);
        return total + measurements;
    }

    /// <summary>Qubits a gate of <paramref name="kind"/> touches: its controls, named by leading C's, and its target (SWAP two).</summary>
    public static int QubitsOf(string kind)
    {
        ArgumentNullException.ThrowIfNull(kind);
        // "CCX" is X with two controls; no intrinsic gate's own name starts with C.
        var controls = kind.TakeWhile(c => c == 'C').Count();
        return controls + (kind[controls..].TrimEnd('†') == "SWAP" ? 2 : 1);
    }

    /// <summary>
    /// The locations of <see cref="LookupIteration"/> on gates of two or more qubits: the phases on the all-ones state (one
    /// per oracle index and one in the diffusion), whose gates are CZ and CCX from n = 2 on; the rest follow one-qubit gates.
    /// </summary>
    public static long LookupIterationMultiQubit(MarkedSet marked)
    {
        ArgumentNullException.ThrowIfNull(marked);
        var n = SearchRegisters.For(marked.Count).IndexQubits;
        if (n < 2) return 0;
        var oracleSize = 2 * marked.MarkedCount > marked.Count ? marked.Count - marked.MarkedCount : marked.MarkedCount;
        return (oracleSize + 1L) * PhaseToAllOnes(n);
    }
}
