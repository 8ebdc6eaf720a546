using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Intersection;

/// <summary>
/// Triangles as the table and the classical tests see them: a watertight test on the fixed-point grid, without
/// division in its decisions. The ray is put on a finer grid (<see cref="FixedRay"/>); with the corners' grid integers
/// it gives three edge functions, each the sign of a triple product computed exactly in integers; the ray hits the
/// triangle when all three signs agree, and its depth is the quotient of two exact products, floored.
/// </summary>
/// <remarks>
/// <para><b>Edge functions.</b> With a = A − O, b = B − O, c = C − O (corners less the ray's origin) and D the ray's
/// direction, E_AB = D · (a × b), E_BC = D · (b × c), E_CA = D · (c × a): the side of each edge's line on which the ray
/// passes, seen along the ray (Plücker coordinates). Their sum is D · N, N = (B − A) × (C − A), whatever the origin.
/// An edge shared by two triangles gets the same value with opposite signs in each, computed exactly, so no ray slips
/// between two triangles (no crack) and none is taken by both on the edge's open part.</para>
/// <para><b>Ties.</b> A ray exactly on an edge's line (E = 0) is moved by an infinitesimal O + ε·x̂ + ε²·ŷ + ε³·ẑ, the
/// same for every triangle. E is linear in O, so the moved sign is that of the first non-zero of E, (D × e).x,
/// (D × e).y, (D × e).z, e the edge vector: exact, and opposite for the two triangles of a shared edge. A ray through
/// a shared corner is then inside exactly one triangle of a fan that covers the corner (the moved ray passes through
/// no corner). A ray in the triangle's plane (D · N = 0) never hits it.</para>
/// <para><b>Depth.</b> The ray meets the plane at t = N · a / N · D (in the fixed ray's direction units); its depth
/// along the principal axis, in grid units, is floor(N · a · 2^(S − R) / N · D), with the direction's principal
/// component 2^S and the origin's R fraction bits below a grid step: a division a circuit would replace by comparing
/// N · a · 2^(S − R) with (depth limit) · N · D, a cross-multiplication. The hit must lie ahead of the origin (N · a
/// of the sign of N · D) and within the ray's end.</para>
/// <para><b>Eight at a time.</b> <see cref="AppendInside"/> evaluates the edge functions in double precision eight
/// triangles per step with a bound on their rounding error; a triangle two of whose edge functions certainly differ in
/// sign is certainly missed, and every other one takes the exact row. Which rows are kept is the exact test's alone,
/// so the kernel's rows are the scalar ones.</para>
/// </remarks>
public sealed class TriangleRows : PrimitiveRows
{
    private readonly IReadOnlyList<Triangle> _triangles;

    // Per triangle: the corners as grid integers (A, B, C, x y z each) and N = (B − A) × (C − A) in grid units.
    private readonly long[] _corners;
    private readonly long[] _normals;

    // Columns for the kernel: corner k's coordinate on axis j in fine units (grid integer · 2^R), exact in a double.
    private readonly double[][] _columns;

    public TriangleRows(CoordinateGrid grid, int first, IReadOnlyList<Triangle> triangles)
        : base(grid, first, triangles.Count)
    {
        _triangles = triangles;
        _corners = new long[Count * 9];
        _normals = new long[Count * 3];
        for (var i = 0; i < Count; i++)
        {
            for (var k = 0; k < 3; k++)
                for (var axis = 0; axis < 3; axis++)
                    _corners[i * 9 + k * 3 + axis] = Grid.ToFixed(triangles[i][k][axis])
                        ?? throw new ArgumentException($"triangle {first + i}: coordinate {triangles[i][k][axis]} is not on the {Grid}");
            var (ab, ac) = (Edge(i, 0, 1), Edge(i, 0, 2));
            (_normals[i * 3], _normals[i * 3 + 1], _normals[i * 3 + 2]) = Cross(ab, ac);
            if (_normals[i * 3] == 0 && _normals[i * 3 + 1] == 0 && _normals[i * 3 + 2] == 0)
                throw new ArgumentException($"triangle {first + i} has no area on the {Grid}");
        }
        _columns = [.. Enumerable.Range(0, 9).Select(j => Enumerable.Range(0, Count).Select(i => (double)(_corners[i * 9 + j] << FixedRay.OriginFractionBits)).ToArray())];
    }

    public override TableRow Row(Ray ray, int p)
    {
        if (p == ray.ExcludedPrimitive || FixedRay.Of(ray, Scale) is not { } fixedRay) return default;
        var i = p - First;
        return MayHit(fixedRay, i) ? Exact(ray, fixedRay, i) : default;
    }

    /// <summary>The exact test alone, without the double-precision filter <see cref="Row"/> runs first: what the filter must never change.</summary>
    internal TableRow ExactRow(Ray ray, int p) =>
        p == ray.ExcludedPrimitive || FixedRay.Of(ray, Scale) is not { } fixedRay ? default : Exact(ray, fixedRay, p - First);

    /// <summary>Always: a triangle's row is valid only where the ray hits it.</summary>
    public override bool Inside(int p, int x, int y, int z) => true;

    /// <summary>
    /// The triangle's corners widened by one grid step: the fixed ray strays from the ray by far less than a step, and
    /// a box one step wider is entered at least a step before any hit inside it, so its quantised entry depth never
    /// passes the hit's.
    /// </summary>
    public override (Vec3 Min, Vec3 Max) Bounds(int p)
    {
        var (min, max) = _triangles[p - First].Bounds;
        var step = new Vec3(Grid.Step, Grid.Step, Grid.Step);
        return (min - step, max + step);
    }

    public override void AppendInside(Ray ray, Span<RayTable.KeptRow> rows, ref int count, ref int maxDepth)
    {
        if (FixedRay.Of(ray, Scale) is not { } fixedRay) return;
        var i = 0;
        if (Vector512.IsHardwareAccelerated || Vector256.IsHardwareAccelerated)
            i = Vectorised(ray, fixedRay, rows, ref count, ref maxDepth);
        for (; i < Count; i++)
            if (First + i != ray.ExcludedPrimitive && MayHit(fixedRay, i)) Keep(ray, fixedRay, i, rows, ref count, ref maxDepth);
    }

    // The exact row of triangle i, kept when the ray hits it.
    private void Keep(Ray ray, FixedRay fixedRay, int i, Span<RayTable.KeptRow> rows, ref int count, ref int maxDepth)
    {
        var row = Exact(ray, fixedRay, i);
        if (!row.Valid) return;
        maxDepth = Math.Max(maxDepth, row.Depth);
        rows[count++] = new(First + i, row.Depth, row.Distance);
    }

    // The exact test: edge signs with the tie rule, then the depth (class remarks).
    private TableRow Exact(Ray ray, FixedRay f, int i)
    {
        var (a, b, c) = (Relative(f, i, 0), Relative(f, i, 1), Relative(f, i, 2));
        var sideAb = Side(EdgeFunction(f, a, b), f, Edge(i, 0, 1));
        if (sideAb == 0) return default;
        if (Side(EdgeFunction(f, b, c), f, Edge(i, 1, 2)) != sideAb || Side(EdgeFunction(f, c, a), f, Edge(i, 2, 0)) != sideAb) return default;
        var (nx, ny, nz) = (_normals[i * 3], _normals[i * 3 + 1], _normals[i * 3 + 2]);
        var along = Math.BigMul(nx, f.Dx) + Math.BigMul(ny, f.Dy) + Math.BigMul(nz, f.Dz);
        var ahead = Math.BigMul(nx, a.X) + Math.BigMul(ny, a.Y) + Math.BigMul(nz, a.Z);
        if (along < 0) (along, ahead) = (-along, -ahead);
        if (ahead <= 0) return default;
        var scaled = ahead << (FixedRay.DirectionBits - FixedRay.OriginFractionBits);
        var quotient = scaled / along;
        var depth = quotient >= int.MaxValue ? int.MaxValue : (int)quotient;
        var (origin, direction) = (ray.Origin, ray.Direction);
        var principal = Math.Max(Math.Abs(direction.X), Math.Max(Math.Abs(direction.Y), Math.Abs(direction.Z)));
        var distance = (double)scaled / (double)along / Scale / principal;
        if (!(distance > RayTable.SnapTolerance) || distance >= ray.MaxDistance) return default;
        var scale = Scale;
        return new TableRow(true, RayTable.Quantise(origin.X + distance * direction.X, scale), RayTable.Quantise(origin.Y + distance * direction.Y, scale),
            RayTable.Quantise(origin.Z + distance * direction.Z, scale), depth, distance);
    }

    // E = D · (a × b), exact: a and b are below 2^42 in magnitude, so each product of the cross product fits 128 bits.
    private static Int128 EdgeFunction(FixedRay f, (long X, long Y, long Z) a, (long X, long Y, long Z) b) =>
        (Math.BigMul(a.Y, b.Z) - Math.BigMul(a.Z, b.Y)) * f.Dx
        + (Math.BigMul(a.Z, b.X) - Math.BigMul(a.X, b.Z)) * f.Dy
        + (Math.BigMul(a.X, b.Y) - Math.BigMul(a.Y, b.X)) * f.Dz;

    // The sign of an edge function moved by the tie rule: E's, or on the line the first non-zero of D × e.
    private static int Side(Int128 e, FixedRay f, (long X, long Y, long Z) edge)
    {
        if (e != 0) return e > 0 ? 1 : -1;
        var (x, y, z) = Cross((f.Dx, f.Dy, f.Dz), edge);
        return x != 0 ? Math.Sign(x) : y != 0 ? Math.Sign(y) : Math.Sign(z);
    }

    // Corner k of triangle i less the origin, in fine units.
    private (long X, long Y, long Z) Relative(FixedRay f, int i, int k) => (
        (_corners[i * 9 + k * 3] << FixedRay.OriginFractionBits) - f.Ox,
        (_corners[i * 9 + k * 3 + 1] << FixedRay.OriginFractionBits) - f.Oy,
        (_corners[i * 9 + k * 3 + 2] << FixedRay.OriginFractionBits) - f.Oz);

    // Corner `to` less corner `from` of triangle i, in grid units.
    private (long X, long Y, long Z) Edge(int i, int from, int to) => (
        _corners[i * 9 + to * 3] - _corners[i * 9 + from * 3],
        _corners[i * 9 + to * 3 + 1] - _corners[i * 9 + from * 3 + 1],
        _corners[i * 9 + to * 3 + 2] - _corners[i * 9 + from * 3 + 2]);

    private static (long X, long Y, long Z) Cross((long X, long Y, long Z) u, (long X, long Y, long Z) v) =>
        (u.Y * v.Z - u.Z * v.Y, u.Z * v.X - u.X * v.Z, u.X * v.Y - u.Y * v.X);

    // The double-precision filter for one triangle: false only when two edge functions certainly differ in sign.
    private bool MayHit(FixedRay f, int i)
    {
        var (positive, negative) = (false, false);
        for (var k = 0; k < 3; k++)
        {
            var (from, to) = (k, (k + 1) % 3);
            var (ax, ay, az) = (_columns[from * 3][i] - f.Ox, _columns[from * 3 + 1][i] - f.Oy, _columns[from * 3 + 2][i] - f.Oz);
            var (bx, by, bz) = (_columns[to * 3][i] - f.Ox, _columns[to * 3 + 1][i] - f.Oy, _columns[to * 3 + 2][i] - f.Oz);
            var e = (ay * bz - az * by) * f.Dx + (az * bx - ax * bz) * f.Dy + (ax * by - ay * bx) * f.Dz;
            var bound = ErrorBound * Math.Max(Math.Abs(ax), Math.Max(Math.Abs(ay), Math.Abs(az))) * Math.Max(Math.Abs(bx), Math.Max(Math.Abs(by), Math.Abs(bz))) * f.Norm1;
            positive |= e > bound;
            negative |= e < -bound;
        }
        return !(positive && negative);
    }

    /// <summary>
    /// A bound on the rounding error of an edge function evaluated in double precision, relative to
    /// max|a| · max|b| · |D|₁: each of its six terms is a product of three exact values at most that size, and the
    /// evaluation rounds each term at most twice and the sums at most three times (5 units of 2^−53, taken as 32).
    /// </summary>
    private const double ErrorBound = 2 * 32 * 1.1102230246251565e-16;

    // Full steps of eight triangles; returns the first (local index) left for the scalar loop.
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private int Vectorised(Ray ray, FixedRay f, Span<RayTable.KeptRow> rows, ref int count, ref int maxDepth)
    {
        var (ox, oy, oz) = (Vector512.Create((double)f.Ox), Vector512.Create((double)f.Oy), Vector512.Create((double)f.Oz));
        var (dx, dy, dz) = (Vector512.Create((double)f.Dx), Vector512.Create((double)f.Dy), Vector512.Create((double)f.Dz));
        var norm = Vector512.Create(ErrorBound * f.Norm1);
        var i = 0;
        for (; i + Vector512<double>.Count <= Count; i += Vector512<double>.Count)
        {
            var (ax, ay, az) = (Load(0, i) - ox, Load(1, i) - oy, Load(2, i) - oz);
            var (bx, by, bz) = (Load(3, i) - ox, Load(4, i) - oy, Load(5, i) - oz);
            var (cx, cy, cz) = (Load(6, i) - ox, Load(7, i) - oy, Load(8, i) - oz);
            var (ma, mb, mc) = (Largest(ax, ay, az), Largest(bx, by, bz), Largest(cx, cy, cz));
            var (eab, bab) = (EdgeFunction(ax, ay, az, bx, by, bz, dx, dy, dz), ma * mb * norm);
            var (ebc, bbc) = (EdgeFunction(bx, by, bz, cx, cy, cz, dx, dy, dz), mb * mc * norm);
            var (eca, bca) = (EdgeFunction(cx, cy, cz, ax, ay, az, dx, dy, dz), mc * ma * norm);
            var positive = Vector512.GreaterThan(eab, bab) | Vector512.GreaterThan(ebc, bbc) | Vector512.GreaterThan(eca, bca);
            var negative = Vector512.LessThan(eab, -bab) | Vector512.LessThan(ebc, -bbc) | Vector512.LessThan(eca, -bca);
            var lanes = (~(positive & negative)).ExtractMostSignificantBits();
            while (lanes != 0)
            {
                var lane = System.Numerics.BitOperations.TrailingZeroCount(lanes);
                lanes &= lanes - 1;
                if (First + i + lane != ray.ExcludedPrimitive) Keep(ray, f, i + lane, rows, ref count, ref maxDepth);
            }
        }
        return i;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private Vector512<double> Load(int column, int i) => Vector512.Create(_columns[column].AsSpan(i));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector512<double> Largest(Vector512<double> x, Vector512<double> y, Vector512<double> z) =>
        Vector512.Max(Vector512.Abs(x), Vector512.Max(Vector512.Abs(y), Vector512.Abs(z)));

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector512<double> EdgeFunction(Vector512<double> ax, Vector512<double> ay, Vector512<double> az,
        Vector512<double> bx, Vector512<double> by, Vector512<double> bz, Vector512<double> dx, Vector512<double> dy, Vector512<double> dz) =>
        (ay * bz - az * by) * dx + (az * bx - ax * bz) * dy + (ax * by - ay * bx) * dz;
}
