using System.Numerics;
using QuantumRayTracing.Intersection;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// What fixes the cost of one gate-level search's circuit, apart from r: the number of rows N and the
/// index bits, the coordinate and depth bits, and how much of each comparator with a constant is
/// built (<see cref="ComparatorBits"/>). Two rays with the same shape have the same circuit up to
/// which X gates load their data, so the same logical counts.
/// </summary>
/// <param name="Primitives">N, the rows the lookups read.</param>
/// <param name="IndexBits">ceil(log2 N).</param>
/// <param name="CoordinateBits">Bits per coordinate.</param>
/// <param name="DepthBits">The ray's depth bits.</param>
/// <param name="NearBits">The near comparator (depth ≥ Near): <see cref="ComparatorBits"/> on the depth register.</param>
/// <param name="LimitBits">The limit comparator ((depth, id) below Limit): <see cref="ComparatorBits"/> on depth and index.</param>
public readonly record struct OracleShape(int Primitives, int IndexBits, int CoordinateBits, int DepthBits, int NearBits, int LimitBits)
{
    public static OracleShape Of(OracleInput input)
    {
        ArgumentNullException.ThrowIfNull(input);
        var constants = OracleConstants.For(input);
        var depth = input.Table.DepthBits;
        var index = input.Geometry.IndexBits;
        return new OracleShape(input.Table.Count, index, input.Table.CoordinateBits, depth,
            ComparatorBits(constants.Near, depth), ComparatorBits(constants.Limit, depth + index));
    }

    /// <summary>
    /// The part of a comparison with constant k on w qubits that costs gates: 0 when it always holds
    /// or never does (k ≤ 0, or k ≥ 2^w: then w + 1), else the w − tz(k) bits above k's trailing
    /// zeros (the library compares only those).
    /// </summary>
    public static int ComparatorBits(long constant, int width) =>
        constant <= 0 ? 0 : constant >= 1L << width ? width + 1 : width - BitOperations.TrailingZeroCount(constant);

    public override string ToString() =>
        $"N {Primitives}, {IndexBits} index, {CoordinateBits} coordinate, {DepthBits} depth bits, comparators {NearBits}/{LimitBits}";
}
