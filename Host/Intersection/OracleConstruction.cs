namespace QuantumRayTracing.Intersection;

/// <summary>
/// How the gate-level oracle is built (the Q# struct of the same name): every construction marks the
/// same rows, and differs in lookups, comparators and qubits.
/// </summary>
/// <param name="Name">What the command line and the tables call it.</param>
/// <param name="InPlaneAxes">Test only the two axes in each primitive's plane: on the flat axis the point is the plane and min = max, so that test always passes.</param>
/// <param name="BothBounds">Load an axis's minimum and maximum into two registers at once instead of turning one into the other with a lookup.</param>
/// <param name="MeasuredUnload">Clear the loaded registers with the measurement-based unlookup (few Toffolis, 2^⌊n/2⌋ + 2^⌈n/2⌉ − n − 2 auxiliaries) rather than a second lookup.</param>
/// <param name="ConstantBounds">Load no bound: compare the point with each primitive's bounds as constants, each comparison controlled on the index holding that primitive (no bound register; 2N controlled comparators per axis).</param>
public sealed record OracleConstruction(string Name, bool InPlaneAxes, bool BothBounds, bool MeasuredUnload, bool ConstantBounds = false)
{
    /// <summary>The first construction (paper fig. 4 axis by axis, one bound register): the "before" of docs/oracle-sweep.md.</summary>
    public static readonly OracleConstruction Baseline = new("baseline", InPlaneAxes: false, BothBounds: false, MeasuredUnload: true);

    /// <summary>Two in-plane axes, both bounds at once, measured unloads: the fewest Toffolis.</summary>
    public static readonly OracleConstruction Compact = new("compact", InPlaneAxes: true, BothBounds: true, MeasuredUnload: true);

    /// <summary>As <see cref="Compact"/> but unloading by lookup: more Toffolis, no power-product auxiliaries.</summary>
    public static readonly OracleConstruction Narrow = new("narrow", InPlaneAxes: true, BothBounds: true, MeasuredUnload: false);

    /// <summary>
    /// Two in-plane axes with the bounds as constants under index control: the fewest qubits, for the paper's device
    /// experiment on a 27-qubit machine (docs/oracle-sweep.md).
    /// </summary>
    public static readonly OracleConstruction Device = new("device", InPlaneAxes: true, BothBounds: false, MeasuredUnload: true, ConstantBounds: true);

    /// <summary>What the gate engine and the estimates use unless told otherwise.</summary>
    public static OracleConstruction Default => Compact;

    public static IReadOnlyList<OracleConstruction> Named { get; } = [Baseline, Compact, Narrow, Device];

    /// <summary>Axes tested per primitive: 2 or 3.</summary>
    public int Axes => InPlaneAxes ? 2 : 3;

    /// <summary>Coordinate registers holding bounds: 0 (constants), 1 (minimum, then maximum) or 2.</summary>
    public int BoundRegisters => ConstantBounds ? 0 : BothBounds ? 2 : 1;

    public override string ToString() => Name;
}
