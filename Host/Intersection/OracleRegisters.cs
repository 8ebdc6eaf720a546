using QuantumRayTracing.Search;

namespace QuantumRayTracing.Intersection;

/// <summary>
/// The qubits one gate-level search holds (paper figs. 3-5): the index register; the work registers
/// rpc and coord (reused axis by axis; coord holds one or two bounds), depth, and the flags (valid, one
/// per tested axis, near, limit); the output qubit (the phase qubit held in |1⟩ in a Grover search);
/// plus the auxiliary qubits the standard library allocates inside its gates and releases clean, of
/// which the widest moment counts.
/// </summary>
/// <param name="IndexQubits">ceil(log2 N).</param>
/// <param name="CoordinateQubits">The grid's bits; rpc and each bound register take this many.</param>
/// <param name="BoundRegisters">Coordinate registers holding bounds: 1 or 2 (<see cref="OracleConstruction.BoundRegisters"/>).</param>
/// <param name="DepthQubits">The table's depth bits.</param>
/// <param name="FlagQubits">valid (not with constant bounds), one per tested axis, near, limit.</param>
/// <param name="AuxiliaryQubits">Peak auxiliaries inside library gates (see <see cref="For"/>).</param>
public readonly record struct OracleRegisters(
    int IndexQubits, int CoordinateQubits, int BoundRegisters, int DepthQubits, int FlagQubits, int AuxiliaryQubits)
{
    /// <summary>The qubit i_r(p) is XORed into, or the Grover search's phase qubit.</summary>
    public const int OutputQubits = 1;

    /// <summary>rpc and the bound registers.</summary>
    public int CoordinateRegisterQubits => (1 + BoundRegisters) * CoordinateQubits;

    /// <summary>The oracle's own ancilla registers, all back in |0⟩ after each call: Q#'s IntersectionWorkQubits.</summary>
    public int WorkQubits => CoordinateRegisterQubits + DepthQubits + FlagQubits;

    /// <summary>Qubits allocated by the search's own registers: index, work and output.</summary>
    public int RegisterQubits => IndexQubits + WorkQubits + OutputQubits;

    /// <summary>Peak qubits in use, auxiliaries included: what the Resource Estimator reports.</summary>
    public int PeakQubits => RegisterQubits + AuxiliaryQubits;

    /// <summary>Every qubit that starts and ends in |0⟩ around an oracle call: work registers and library auxiliaries.</summary>
    public int AncillaQubits => WorkQubits + AuxiliaryQubits;

    /// <summary>The registers of a Grover search with the oracle: the reflection's auxiliaries count too.</summary>
    public static OracleRegisters For(OracleInput input) => Model(input, withReflection: true);

    /// <summary>The registers of the oracle Int_r applied once on its own (no reflection).</summary>
    public static OracleRegisters ForOracle(OracleInput input) => Model(input, withReflection: false);

    /// <remarks>
    /// The auxiliaries are those of the widest step, one step at a time: a lookup (n − 1 nested
    /// helpers), the measurement-based unlookup when the construction uses it (the phase lookup's
    /// power products, 2^⌊n/2⌋ − ⌊n/2⌋ − 1 + 2^⌈n/2⌉ − ⌈n/2⌉ − 1), a register comparator (c carries), a
    /// comparator with a constant k on w qubits (w − 1 − trailing zeros of k, none when k is 0 or 2^w),
    /// with constant bounds each primitive's comparators under the n index controls (the comparator's and
    /// those of its action's n + 1 controls, <see cref="ControlledBoundComparators"/>), the flags'
    /// multi-controlled gate (flags − 2) and, in a search, the reflection's multi-controlled Z (n − 2).
    /// </remarks>
    private static OracleRegisters Model(OracleInput input, bool withReflection)
    {
        ArgumentNullException.ThrowIfNull(input);
        var n = input.Geometry.IndexBits;
        var c = input.Table.CoordinateBits;
        var d = input.Table.DepthBits;
        var construction = input.Construction;
        // valid (none with constant bounds: a row without a point clears an axis flag), one per axis, near, limit.
        var flags = construction.Axes + (construction.ConstantBounds ? 2 : 3);
        var constants = OracleConstants.For(input);
        var lookups = input.Geometry.Count <= 1 ? 0
            : construction.MeasuredUnload ? Math.Max(n - 1, PowerProducts(n / 2) + PowerProducts(n - n / 2))
            : n - 1;
        var auxiliary = new[]
        {
            lookups,
            construction.ConstantBounds ? ControlledBoundComparators(input) : c,
            ConstantComparator(constants.Near, d),
            ConstantComparator(constants.Limit, n + d),
            flags - 2,
            withReflection ? SearchRegisters.For(input.Geometry.Count).AuxiliaryQubits : 0,
        }.Max();
        return new OracleRegisters(n, c, construction.BoundRegisters, d, flags, auxiliary);
    }

    /// <summary>
    /// Peak auxiliaries of the constant-bound comparisons: minimum ≤ rpc and rpc ≤ maximum (rpc ≥ maximum + 1 inverted) for
    /// each primitive's tested axes, each controlled on its index: a constant strictly inside 1..2^c − 1 takes the comparator's
    /// carries and the action's n + 1 controls (n − 1 more); at 0 or 2^c the action alone runs under the n controls (n − 2), as
    /// does the X that clears a row without a point.
    /// </summary>
    private static int ControlledBoundComparators(OracleInput input)
    {
        var (geometry, c) = (input.Geometry, input.Table.CoordinateBits);
        var n = geometry.IndexBits;
        int Comparator(long constant) => constant <= 0 || constant >= 1L << c
            ? Math.Max(0, n - 2)
            : ConstantComparator(constant, c) + Math.Max(0, n - 1);
        // Rows without a point and indices past the last primitive get one X under the n controls; valid rows their comparators.
        var peak = Math.Max(0, n - 2);
        for (var p = 0; p < geometry.Count; p++)
            for (var axis = 0; axis < 3 && input.Table.IsValid(p); axis++)
                if (!input.Construction.InPlaneAxes || axis != geometry.FlatAxis(p))
                    peak = Math.Max(peak, Math.Max(Comparator(geometry.Min(p, axis)), Comparator(geometry.Max(p, axis) + 1L)));
        return peak;
    }

    private static int PowerProducts(int bits) => (1 << bits) - bits - 1;

    private static int ConstantComparator(long constant, int width) =>
        constant <= 0 || constant >= 1L << width ? 0 : width - 1 - (int)long.TrailingZeroCount(constant);
}
