using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using QuantumRayTracing.Rays;

namespace QuantumRayTracing.Intersection;

/// <summary>
/// eval-rpc and verify-rpc's bounds test for one ray against every primitive, eight primitives per step
/// (<see cref="Vector512{T}"/> over <see cref="SceneGeometry"/>'s columns): the rows whose point lies inside their
/// rectangle, and the largest depth of any valid row. Every lane makes the same IEEE operations in the same order as
/// <see cref="RayTable.EvaluateRow"/> (no fused multiply-add), so the rows are bit for bit the scalar ones; the
/// primitives past the last full step, and machines without 256-bit vectors, take the scalar row. Where 512-bit vectors
/// are not in hardware, .NET runs each step as two 256-bit halves.
/// </summary>
internal static class CompactRows
{
    /// <summary>
    /// Fills <paramref name="rows"/> (at least N long) with the inside rows in ascending order; returns how many, and the
    /// largest depth of a valid row (0 for none).
    /// </summary>
    public static int Evaluate(SceneGeometry geometry, Ray ray, Span<RayTable.KeptRow> rows, out int maxDepth)
    {
        var count = 0;
        maxDepth = 0;
        var p = 0;
        if (Vector512.IsHardwareAccelerated || Vector256.IsHardwareAccelerated)
            p = Vectorised(geometry, ray, rows, ref count, ref maxDepth);
        for (; p < geometry.Count; p++)
        {
            var row = RayTable.EvaluateRow(geometry, ray, p);
            if (!row.Valid) continue;
            maxDepth = Math.Max(maxDepth, row.Depth);
            if (!RayTable.Inside(geometry, p, row.X, row.Y, row.Z)) continue;
            rows[count++] = new(p, row.Depth, row.Distance);
        }
        return count;
    }

    // The full steps of eight primitives; returns the first primitive left for the scalar row. Compiled fully optimised at
    // its first call: left to tiering, a render's first tiles ran it unoptimised while other methods were still compiled.
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private static int Vectorised(SceneGeometry geometry, Ray ray, Span<RayTable.KeptRow> rows, ref int count, ref int maxDepth)
    {
        var (origin, direction) = (ray.Origin, ray.Direction);
        var (ox, oy, oz) = (Vector512.Create(origin.X), Vector512.Create(origin.Y), Vector512.Create(origin.Z));
        var (dx, dy, dz) = (Vector512.Create(direction.X), Vector512.Create(direction.Y), Vector512.Create(direction.Z));
        var principal = Vector512.Create(Math.Max(Math.Abs(direction.X), Math.Max(Math.Abs(direction.Y), Math.Abs(direction.Z))));
        var scale = Vector512.Create(geometry.Scale);
        var snap = Vector512.Create(RayTable.SnapTolerance);
        var parallel = Vector512.Create(1e-12);
        var end = Vector512.Create(ray.MaxDistance);
        var limit = Vector512.Create((double)(1 << geometry.Grid.Bits));
        var zero = Vector512<double>.Zero;
        var deepest = Vector512.Create(-1.0);
        var laneIndices = Vector512.Create(0.0, 1, 2, 3, 4, 5, 6, 7);
        var excluded = Vector512.Create((double)ray.ExcludedPrimitive);
        var (flatX, flatY, flatZ) = (geometry.FlatMasks[0], geometry.FlatMasks[1], geometry.FlatMasks[2]);
        var (minX, minY, minZ) = (geometry.MinColumns[0], geometry.MinColumns[1], geometry.MinColumns[2]);
        var (maxX, maxY, maxZ) = (geometry.MaxColumns[0], geometry.MaxColumns[1], geometry.MaxColumns[2]);
        var planes = geometry.Planes;
        var p = 0;
        for (; p + Vector512<double>.Count <= geometry.Count; p += Vector512<double>.Count)
        {
            var onX = Vector512.Create(flatX.AsSpan(p)).AsDouble();
            var onY = Vector512.Create(flatY.AsSpan(p)).AsDouble();
            var along = Vector512.ConditionalSelect(onX, dx, Vector512.ConditionalSelect(onY, dy, dz));
            var start = Vector512.ConditionalSelect(onX, ox, Vector512.ConditionalSelect(onY, oy, oz));
            var t = (Load(planes, p) - start) / along;
            var valid = ~Vector512.Equals(Vector512.Create((double)p) + laneIndices, excluded)
                & ~Vector512.LessThan(Vector512.Abs(along), parallel) & Vector512.GreaterThan(t, snap) & ~Vector512.GreaterThanOrEqual(t, end);
            var lowX = Load(minX, p);
            var lowY = Load(minY, p);
            var lowZ = Load(minZ, p);
            var x = Vector512.ConditionalSelect(onX, lowX, Quantise(ox + t * dx, scale, snap));
            var y = Vector512.ConditionalSelect(onY, lowY, Quantise(oy + t * dy, scale, snap));
            var onZ = Vector512.Create(flatZ.AsSpan(p)).AsDouble();
            var z = Vector512.ConditionalSelect(onZ, lowZ, Quantise(oz + t * dz, scale, snap));
            var depth = Quantise(t * principal, scale, snap);
            valid &= OnGrid(x, limit) & OnGrid(y, limit) & OnGrid(z, limit) & Vector512.GreaterThanOrEqual(depth, zero);
            deepest = Vector512.Max(deepest, Vector512.ConditionalSelect(valid, depth, deepest));
            var inside = valid
                & Vector512.GreaterThanOrEqual(x, lowX) & Vector512.LessThanOrEqual(x, Load(maxX, p))
                & Vector512.GreaterThanOrEqual(y, lowY) & Vector512.LessThanOrEqual(y, Load(maxY, p))
                & Vector512.GreaterThanOrEqual(z, lowZ) & Vector512.LessThanOrEqual(z, Load(maxZ, p));
            var lanes = inside.ExtractMostSignificantBits();
            while (lanes != 0)
            {
                var lane = System.Numerics.BitOperations.TrailingZeroCount(lanes);
                lanes &= lanes - 1;
                rows[count++] = new(p + lane, ToInt(depth.GetElement(lane)), t.GetElement(lane));
            }
        }
        for (var lane = 0; lane < Vector512<double>.Count; lane++) maxDepth = Math.Max(maxDepth, deepest.GetElement(lane) < 0 ? 0 : ToInt(deepest.GetElement(lane)));
        return p;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector512<double> Load(double[] column, int p) => Vector512.Create(column.AsSpan(p));

    // RayTable.Quantise before its conversion to int: floor(value · scale + snap).
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector512<double> Quantise(Vector512<double> value, Vector512<double> scale, Vector512<double> snap) => Vector512.Floor(value * scale + snap);

    // 0 ≤ value < 2^bits: the scalar row's saturated int inside the grid.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector512<double> OnGrid(Vector512<double> value, Vector512<double> limit) =>
        Vector512.GreaterThanOrEqual(value, Vector512<double>.Zero) & Vector512.LessThan(value, limit);

    // RayTable.Quantise's saturation of an already floored value. Inlined by request: the kernel, compiled before any
    // profile, otherwise calls it once per kept row.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int ToInt(double scaled) => scaled >= int.MaxValue ? int.MaxValue : scaled <= int.MinValue ? int.MinValue : (int)scaled;
}
