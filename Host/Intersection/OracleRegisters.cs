using QuantumRayTracing.Search;

namespace QuantumRayTracing.Intersection;

/// <summary>
/// The qubits one gate-level Grover search holds (paper figs. 3-5): the index register, the rpc and
/// coord registers (one coordinate each, reused axis by axis), the depth register, six flags (valid,
/// i_X, i_Y, i_Z, near, limit) and the phase qubit held in |1⟩; plus the auxiliary qubits the
/// standard library allocates inside its gates and releases clean, of which the widest moment counts.
/// </summary>
/// <param name="IndexQubits">ceil(log2 N).</param>
/// <param name="CoordinateQubits">The grid's bits; rpc and coord take this many each.</param>
/// <param name="DepthQubits">The table's depth bits.</param>
/// <param name="AuxiliaryQubits">Peak auxiliaries inside library gates (see <see cref="For"/>).</param>
public readonly record struct OracleRegisters(int IndexQubits, int CoordinateQubits, int DepthQubits, int AuxiliaryQubits)
{
    /// <summary>valid, i_X, i_Y, i_Z, near, limit.</summary>
    public const int FlagQubits = 6;

    /// <summary>The qubit the flags' AND kicks its phase back from.</summary>
    public const int PhaseQubits = 1;

    /// <summary>Qubits allocated by the search's own registers: n + 2c + d + 7.</summary>
    public int RegisterQubits => IndexQubits + 2 * CoordinateQubits + DepthQubits + FlagQubits + PhaseQubits;

    /// <summary>Peak qubits in use, auxiliaries included: what the Resource Estimator reports.</summary>
    public int PeakQubits => RegisterQubits + AuxiliaryQubits;

    /// <remarks>
    /// The auxiliaries are those of the widest step, one step at a time: a lookup (n − 1 nested
    /// helpers), its measurement-based unlookup (the phase lookup's power products,
    /// 2^⌊n/2⌋ − ⌊n/2⌋ − 1 + 2^⌈n/2⌉ − ⌈n/2⌉ − 1), a register comparator (c carries), a comparator with
    /// a constant k on w qubits (w − 1 − trailing zeros of k, none when k is 0 or 2^w), the
    /// six-controlled Z (4) and the reflection's multi-controlled Z (n − 2).
    /// </remarks>
    public static OracleRegisters For(OracleInput input)
    {
        ArgumentNullException.ThrowIfNull(input);
        var n = input.Geometry.IndexBits;
        var c = input.Table.CoordinateBits;
        var d = input.Table.DepthBits;
        var constants = OracleConstants.For(input);
        var lookups = input.Geometry.Count > 1 ? Math.Max(n - 1, PowerProducts(n / 2) + PowerProducts(n - n / 2)) : 0;
        var auxiliary = new[]
        {
            lookups,
            c,
            ConstantComparator(constants.Near, d),
            ConstantComparator(constants.Limit, n + d),
            FlagQubits - 2,
            SearchRegisters.For(input.Geometry.Count).AuxiliaryQubits,
        }.Max();
        return new OracleRegisters(n, c, d, auxiliary);
    }

    private static int PowerProducts(int bits) => (1 << bits) - bits - 1;

    private static int ConstantComparator(long constant, int width) =>
        constant <= 0 || constant >= 1L << width ? 0 : width - 1 - (int)long.TrailingZeroCount(constant);
}
