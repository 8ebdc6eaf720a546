using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using QuantumRayTracing.Rays;

namespace QuantumRayTracing.Intersection;

/// <summary>
/// eval-rpc and verify-rpc's bounds test for one ray against every primitive, four primitives per step
/// (<see cref="Vector256{T}"/> over <see cref="SceneGeometry"/>'s columns): the rows whose point lies inside their
/// rectangle, and the largest depth of any valid row. Every lane makes the same IEEE operations in the same order as
/// <see cref="RayTable.EvaluateRow"/> (no fused multiply-add), so the rows are bit for bit the scalar ones; the
/// primitives past the last full step, and machines without 256-bit vectors, take the scalar row.
/// </summary>
internal static class CompactRows
{
    /// <summary>
    /// Fills <paramref name="rows"/>, <paramref name="depths"/> and <paramref name="distances"/> (each at least N long)
    /// with the inside rows in ascending order; returns how many, and the largest depth of a valid row (0 for none).
    /// </summary>
    public static int Evaluate(SceneGeometry geometry, Ray ray, Span<int> rows, Span<int> depths, Span<double> distances, out int maxDepth)
    {
        var count = 0;
        maxDepth = 0;
        var p = 0;
        if (Vector256.IsHardwareAccelerated)
            p = Vectorised(geometry, ray, rows, depths, distances, ref count, ref maxDepth);
        for (; p < geometry.Count; p++)
        {
            var row = RayTable.EvaluateRow(geometry, ray, p);
            if (!row.Valid) continue;
            maxDepth = Math.Max(maxDepth, row.Depth);
            if (!RayTable.Inside(geometry, p, row.X, row.Y, row.Z)) continue;
            (rows[count], depths[count], distances[count]) = (p, row.Depth, row.Distance);
            count++;
        }
        return count;
    }

    // The full steps of four primitives; returns the first primitive left for the scalar row.
    private static int Vectorised(SceneGeometry geometry, Ray ray, Span<int> rows, Span<int> depths, Span<double> distances, ref int count, ref int maxDepth)
    {
        var (origin, direction) = (ray.Origin, ray.Direction);
        var (ox, oy, oz) = (Vector256.Create(origin.X), Vector256.Create(origin.Y), Vector256.Create(origin.Z));
        var (dx, dy, dz) = (Vector256.Create(direction.X), Vector256.Create(direction.Y), Vector256.Create(direction.Z));
        var principal = Vector256.Create(Math.Max(Math.Abs(direction.X), Math.Max(Math.Abs(direction.Y), Math.Abs(direction.Z))));
        var scale = Vector256.Create(geometry.Scale);
        var snap = Vector256.Create(RayTable.SnapTolerance);
        var parallel = Vector256.Create(1e-12);
        var end = Vector256.Create(ray.MaxDistance);
        var limit = Vector256.Create((double)(1 << geometry.Grid.Bits));
        var zero = Vector256<double>.Zero;
        var deepest = Vector256.Create(-1.0);
        var lanes0123 = Vector256.Create(0.0, 1, 2, 3);
        var excluded = Vector256.Create((double)ray.ExcludedPrimitive);
        var (flatX, flatY, flatZ) = (geometry.FlatMasks[0], geometry.FlatMasks[1], geometry.FlatMasks[2]);
        var (minX, minY, minZ) = (geometry.MinColumns[0], geometry.MinColumns[1], geometry.MinColumns[2]);
        var (maxX, maxY, maxZ) = (geometry.MaxColumns[0], geometry.MaxColumns[1], geometry.MaxColumns[2]);
        var planes = geometry.Planes;
        var p = 0;
        for (; p + 4 <= geometry.Count; p += 4)
        {
            var onX = Vector256.Create(flatX.AsSpan(p)).AsDouble();
            var onY = Vector256.Create(flatY.AsSpan(p)).AsDouble();
            var along = Vector256.ConditionalSelect(onX, dx, Vector256.ConditionalSelect(onY, dy, dz));
            var start = Vector256.ConditionalSelect(onX, ox, Vector256.ConditionalSelect(onY, oy, oz));
            var t = (Load(planes, p) - start) / along;
            var valid = ~Vector256.Equals(Vector256.Create((double)p) + lanes0123, excluded)
                & ~Vector256.LessThan(Vector256.Abs(along), parallel) & Vector256.GreaterThan(t, snap) & ~Vector256.GreaterThanOrEqual(t, end);
            var lowX = Load(minX, p);
            var lowY = Load(minY, p);
            var lowZ = Load(minZ, p);
            var x = Vector256.ConditionalSelect(onX, lowX, Quantise(ox + t * dx, scale, snap));
            var y = Vector256.ConditionalSelect(onY, lowY, Quantise(oy + t * dy, scale, snap));
            var onZ = Vector256.Create(flatZ.AsSpan(p)).AsDouble();
            var z = Vector256.ConditionalSelect(onZ, lowZ, Quantise(oz + t * dz, scale, snap));
            var depth = Quantise(t * principal, scale, snap);
            valid &= OnGrid(x, limit) & OnGrid(y, limit) & OnGrid(z, limit) & Vector256.GreaterThanOrEqual(depth, zero);
            deepest = Vector256.Max(deepest, Vector256.ConditionalSelect(valid, depth, deepest));
            var inside = valid
                & Vector256.GreaterThanOrEqual(x, lowX) & Vector256.LessThanOrEqual(x, Load(maxX, p))
                & Vector256.GreaterThanOrEqual(y, lowY) & Vector256.LessThanOrEqual(y, Load(maxY, p))
                & Vector256.GreaterThanOrEqual(z, lowZ) & Vector256.LessThanOrEqual(z, Load(maxZ, p));
            var lanes = inside.ExtractMostSignificantBits();
            while (lanes != 0)
            {
                var lane = System.Numerics.BitOperations.TrailingZeroCount(lanes);
                lanes &= lanes - 1;
                (rows[count], depths[count], distances[count]) = (p + lane, ToInt(depth.GetElement(lane)), t.GetElement(lane));
                count++;
            }
        }
        for (var lane = 0; lane < 4; lane++) maxDepth = Math.Max(maxDepth, deepest.GetElement(lane) < 0 ? 0 : ToInt(deepest.GetElement(lane)));
        return p;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector256<double> Load(double[] column, int p) => Vector256.Create(column.AsSpan(p));

    // RayTable.Quantise before its conversion to int: floor(value · scale + snap).
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector256<double> Quantise(Vector256<double> value, Vector256<double> scale, Vector256<double> snap) => Vector256.Floor(value * scale + snap);

    // 0 ≤ value < 2^bits: the scalar row's saturated int inside the grid.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector256<double> OnGrid(Vector256<double> value, Vector256<double> limit) =>
        Vector256.GreaterThanOrEqual(value, Vector256<double>.Zero) & Vector256.LessThan(value, limit);

    // RayTable.Quantise's saturation of an already floored value.
    private static int ToInt(double scaled) => scaled >= int.MaxValue ? int.MaxValue : scaled <= int.MinValue ? int.MinValue : (int)scaled;
}
