using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Intersection;

/// <summary>
/// Axis-aligned rectangles as the table and the classical tests see them (paper sec. 4.1): each rectangle's bounds as
/// fixed-point grid integers (value · 2^FractionBits), its flat axis and plane. eval-rpc meets the plane in floating
/// point and quantises the point; verify-rpc compares it with the bounds.
/// </summary>
/// <remarks>
/// Bounds are the grid cells a quantised point may fall in. Points are quantised by flooring, so a
/// rectangle spanning [a, b) on an axis holds the cells a … b − 1 (one step below its max corner):
/// with the inclusive comparison verify-rpc makes, a point is inside exactly when a ≤ value &lt; b, and
/// rectangles that share an edge never both claim a point. On the flat axis min = max = the plane.
/// <para>
/// <see cref="AppendInside"/> runs eight rectangles per step (<see cref="Vector512{T}"/> over structure-of-arrays
/// columns). Every lane makes the same IEEE operations in the same order as <see cref="Row"/> (no fused multiply-add),
/// so the rows are bit for bit the scalar ones; the rectangles past the last full step, and machines without 256-bit
/// vectors, take the scalar row. Where 512-bit vectors are not in hardware, .NET runs each step as two 256-bit halves.
/// </para>
/// </remarks>
public sealed class RectangleRows : PrimitiveRows
{
    private readonly IReadOnlyList<Rectangle> _rectangles;
    private readonly int[] _min;
    private readonly int[] _max;
    private readonly int[] _flat;
    private readonly double[] _plane;

    // Columns for the vectorised kernel: per axis, the bounds as doubles (grid integers are exact in a double) and the
    // flat-axis masks as all-ones or zero lanes.
    private readonly double[][] _minColumns = [[], [], []];
    private readonly double[][] _maxColumns = [[], [], []];
    private readonly long[][] _flatMasks = [[], [], []];

    public RectangleRows(CoordinateGrid grid, int first, IReadOnlyList<Rectangle> rectangles)
        : base(grid, first, rectangles.Count)
    {
        _rectangles = rectangles;
        _min = new int[Count * 3];
        _max = new int[Count * 3];
        _flat = rectangles.Select(r => r.FlatAxis).ToArray();
        _plane = rectangles.Select(r => r.PlaneOffset).ToArray();
        for (var i = 0; i < Count; i++)
            for (var axis = 0; axis < 3; axis++)
            {
                _min[i * 3 + axis] = ToGrid(rectangles[i].Min[axis], first + i);
                var max = ToGrid(rectangles[i].Max[axis], first + i);
                _max[i * 3 + axis] = axis == rectangles[i].FlatAxis ? max : max - 1;
            }
        for (var axis = 0; axis < 3; axis++)
        {
            var a = axis;
            _minColumns[a] = [.. Enumerable.Range(0, Count).Select(i => (double)_min[i * 3 + a])];
            _maxColumns[a] = [.. Enumerable.Range(0, Count).Select(i => (double)_max[i * 3 + a])];
            _flatMasks[a] = [.. _flat.Select(f => f == a ? -1L : 0L)];
        }
    }

    /// <summary>The axis of rectangle <paramref name="p"/>'s plane normal.</summary>
    public int FlatAxis(int p) => _flat[p - First];

    /// <summary>The world coordinate of rectangle <paramref name="p"/>'s plane along its flat axis.</summary>
    public double PlaneOffset(int p) => _plane[p - First];

    /// <summary>Fixed-point minimum of rectangle <paramref name="p"/> along <paramref name="axis"/>.</summary>
    public int Min(int p, int axis) => _min[(p - First) * 3 + axis];

    /// <summary>The last grid cell of rectangle <paramref name="p"/> along <paramref name="axis"/>: its max corner minus one step, or the plane on the flat axis.</summary>
    public int Max(int p, int axis) => _max[(p - First) * 3 + axis];

    /// <remarks>Written out per axis, without vector indexers: it runs N times for every ray of every pass.</remarks>
    public override TableRow Row(Ray ray, int p)
    {
        var i = p - First;
        var flat = _flat[i];
        var (origin, direction) = (ray.Origin, ray.Direction);
        var along = flat == 0 ? direction.X : flat == 1 ? direction.Y : direction.Z;
        if (p == ray.ExcludedPrimitive || Math.Abs(along) < 1e-12) return default;
        var t = (_plane[i] - (flat == 0 ? origin.X : flat == 1 ? origin.Y : origin.Z)) / along;
        if (!(t > RayTable.SnapTolerance) || t >= ray.MaxDistance) return default;
        var scale = Scale;
        var limit = 1 << Grid.Bits;
        var x = flat == 0 ? _min[i * 3] : RayTable.Quantise(origin.X + t * direction.X, scale);
        if (x < 0 || x >= limit) return default;
        var y = flat == 1 ? _min[i * 3 + 1] : RayTable.Quantise(origin.Y + t * direction.Y, scale);
        if (y < 0 || y >= limit) return default;
        var z = flat == 2 ? _min[i * 3 + 2] : RayTable.Quantise(origin.Z + t * direction.Z, scale);
        if (z < 0 || z >= limit) return default;
        // |direction| along the principal axis is the largest absolute component.
        var principal = Math.Max(Math.Abs(direction.X), Math.Max(Math.Abs(direction.Y), Math.Abs(direction.Z)));
        var depth = RayTable.Quantise(t * principal, scale);
        return depth < 0 ? default : new TableRow(true, x, y, z, depth, t);
    }

    /// <summary>verify-rpc's bounds test: the quantised point lies in the rectangle's cells on every axis.</summary>
    public override bool Inside(int p, int x, int y, int z)
    {
        var i = (p - First) * 3;
        return x >= _min[i] && x <= _max[i] && y >= _min[i + 1] && y <= _max[i + 1] && z >= _min[i + 2] && z <= _max[i + 2];
    }

    public override void AppendInside(Ray ray, Span<RayTable.KeptRow> rows, ref int count, ref int maxDepth)
    {
        var done = 0;
        if (Vector512.IsHardwareAccelerated || Vector256.IsHardwareAccelerated)
            done = Vectorised(ray, rows, ref count, ref maxDepth);
        AppendInside(ray, First + done, rows, ref count, ref maxDepth);
    }

    /// <summary>The rectangle's corners: <see cref="Row"/> meets the plane of the unquantised ray there.</summary>
    public override (Vec3 Min, Vec3 Max) Bounds(int p) => _rectangles[p - First].Bounds;

    // The full steps of eight rectangles; returns the first (local index) left for the scalar row. Compiled fully optimised at
    // its first call: left to tiering, a render's first tiles ran it unoptimised while other methods were still compiled.
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private int Vectorised(Ray ray, Span<RayTable.KeptRow> rows, ref int count, ref int maxDepth)
    {
        var (origin, direction) = (ray.Origin, ray.Direction);
        var (ox, oy, oz) = (Vector512.Create(origin.X), Vector512.Create(origin.Y), Vector512.Create(origin.Z));
        var (dx, dy, dz) = (Vector512.Create(direction.X), Vector512.Create(direction.Y), Vector512.Create(direction.Z));
        var principal = Vector512.Create(Math.Max(Math.Abs(direction.X), Math.Max(Math.Abs(direction.Y), Math.Abs(direction.Z))));
        var scale = Vector512.Create(Scale);
        var snap = Vector512.Create(RayTable.SnapTolerance);
        var parallel = Vector512.Create(1e-12);
        var end = Vector512.Create(ray.MaxDistance);
        var limit = Vector512.Create((double)(1 << Grid.Bits));
        var zero = Vector512<double>.Zero;
        var deepest = Vector512.Create(-1.0);
        var laneIndices = Vector512.Create(0.0, 1, 2, 3, 4, 5, 6, 7);
        var excluded = Vector512.Create((double)ray.ExcludedPrimitive);
        var (flatX, flatY, flatZ) = (_flatMasks[0], _flatMasks[1], _flatMasks[2]);
        var (minX, minY, minZ) = (_minColumns[0], _minColumns[1], _minColumns[2]);
        var (maxX, maxY, maxZ) = (_maxColumns[0], _maxColumns[1], _maxColumns[2]);
        var planes = _plane;
        var first = First;
        var p = 0;
        for (; p + Vector512<double>.Count <= Count; p += Vector512<double>.Count)
        {
            var onX = Vector512.Create(flatX.AsSpan(p)).AsDouble();
            var onY = Vector512.Create(flatY.AsSpan(p)).AsDouble();
            var along = Vector512.ConditionalSelect(onX, dx, Vector512.ConditionalSelect(onY, dy, dz));
            var start = Vector512.ConditionalSelect(onX, ox, Vector512.ConditionalSelect(onY, oy, oz));
            var t = (Load(planes, p) - start) / along;
            var valid = ~Vector512.Equals(Vector512.Create((double)(first + p)) + laneIndices, excluded)
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
                rows[count++] = new(first + p + lane, ToInt(depth.GetElement(lane)), t.GetElement(lane));
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

    private int ToGrid(double value, int p) =>
        Grid.ToFixed(value) ?? throw new ArgumentException($"rectangle {p}: coordinate {value} is not on the {Grid}");
}
