namespace QuantumRayTracing.Intersection;

/// <summary>
/// The gate-level oracle's two comparator constants for one search, clamped to what its registers can
/// hold: <see cref="Near"/> for depth ≥ Near on the DepthBits-qubit depth register, and
/// <see cref="Limit"/> for depth · 2^IndexBits + p &lt; Limit on the depth and index registers read
/// as one number (the strict (depth, id) order, docs/conventions.md).
/// </summary>
/// <remarks>
/// Clamping keeps each comparison exact: a depth register of d qubits holds 0..2^d − 1, so Near ≤ 0
/// always holds and Near ≥ 2^d never does (clamped to 0 and 2^d); a limit depth of 2^d or more (an
/// unbounded far, <see cref="int.MaxValue"/>) always holds (2^(d+n)), a negative one never (0); and
/// as every p is below 2^n, a limit id above 2^n acts as 2^n and a negative one as 0.
/// </remarks>
public readonly record struct OracleConstants(long Near, long Limit)
{
    public static OracleConstants For(OracleInput input)
    {
        ArgumentNullException.ThrowIfNull(input);
        var depthBits = input.Table.DepthBits;
        var indexBits = input.Geometry.IndexBits;
        var window = input.Window;
        var near = Math.Clamp((long)window.Near, 0, 1L << depthBits);
        long limit;
        if (window.LimitDepth < 0) limit = 0;
        else if (window.LimitDepth >= 1L << depthBits) limit = 1L << (depthBits + indexBits);
        else limit = ((long)window.LimitDepth << indexBits) + Math.Clamp(window.LimitId, 0L, 1L << indexBits);
        return new OracleConstants(near, limit);
    }
}
