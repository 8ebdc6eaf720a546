using QuantumRayTracing.Rays;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Intersection;

/// <summary>
/// One ray's lookup table (paper sec. 4.1): for every primitive, eval-rpc's ray/plane point quantised
/// to the scene's fixed-point grid and its depth along the ray's principal axis; and verify-rpc, the
/// integer test the oracle computes with comparators. Building it costs N row evaluations, counted as
/// table rows, never as intersection tests (docs/conventions.md).
/// </summary>
/// <remarks>
/// A row is invalid (no point to load, the primitive cannot be hit) when the ray is parallel to the
/// primitive's plane, the plane is not ahead of the origin or not before the ray's end, the primitive is the one the ray leaves
/// from, or the point falls outside the grid. Coordinates are quantised by flooring (the paper's cast
/// to integers) after adding <see cref="SnapTolerance"/>, so a point a rounding error below a grid line
/// lands on it; the flat axis takes the plane's exact value.
/// <para>
/// A table is full (every row, what the gate-level oracle loads) or <see cref="Compact"/>: only the
/// rows whose point lies inside their rectangle, the only rows any window can accept. Passes keep the
/// compact form of a ray's table between rounds instead of rebuilding N rows.
/// </para>
/// </remarks>
public sealed class RayTable
{
    public const double SnapTolerance = 1e-9;

    // Full form: one entry per primitive in each array, _kept null. Compact form: only _kept, the rows inside their
    // rectangles in ascending order (one array: a compact table is built for every ray of every pass).
    private readonly bool[]? _valid;
    private readonly int[]? _points;
    private readonly int[]? _depths;
    private readonly double[]? _distances;
    private readonly KeptRow[]? _kept;

    /// <summary>A compact table's row: the primitive, its quantised depth and its ray parameter t.</summary>
    public readonly record struct KeptRow(int Primitive, int Depth, double Distance);

    private RayTable(SceneGeometry geometry, Ray ray)
    {
        Geometry = geometry;
        Ray = ray;
        Count = geometry.Count;
        var n = geometry.Count;
        _valid = new bool[n];
        _points = new int[n * 3];
        _depths = new int[n];
        _distances = new double[n];
        var maxDepth = 0;
        for (var p = 0; p < n; p++)
        {
            var row = EvaluateRow(geometry, ray, p);
            if (!row.Valid) continue;
            (_points[p * 3], _points[p * 3 + 1], _points[p * 3 + 2]) = (row.X, row.Y, row.Z);
            _valid[p] = true;
            _depths[p] = row.Depth;
            _distances[p] = row.Distance;
            maxDepth = Math.Max(maxDepth, row.Depth);
        }
        DepthBits = Math.Max(1, 32 - int.LeadingZeroCount(maxDepth));
    }

    private RayTable(RayTable full, int[] rows)
        : this(full.Geometry, full.Ray, full.DepthBits, [.. rows.Select(p => new KeptRow(p, full.Depth(p), full.Distance(p)))])
    {
    }

    private RayTable(SceneGeometry geometry, Ray ray, int depthBits, KeptRow[] kept)
    {
        Geometry = geometry;
        Ray = ray;
        Count = geometry.Count;
        DepthBits = depthBits;
        _kept = kept;
    }

    /// <summary>One row of a ray's table: eval-rpc for primitive <paramref name="p"/> alone, O(1), by its kind's test.</summary>
    public static TableRow EvaluateRow(SceneGeometry geometry, Ray ray, int p) => geometry.KindOf(p).Row(ray, p);

    /// <summary>
    /// One classical ray/primitive intersection test (what #C_Int counts): eval-rpc and verify-rpc for
    /// primitive <paramref name="p"/>; the row when <paramref name="window"/> accepts it, otherwise null.
    /// </summary>
    public static TableRow? Test(SceneGeometry geometry, Ray ray, int p, HitWindow window)
    {
        var row = EvaluateRow(geometry, ray, p);
        return row.Valid && window.Accepts(row.Depth, p) && Inside(geometry, p, row.X, row.Y, row.Z) ? row : null;
    }

    /// <summary>verify-rpc's shape test, by primitive <paramref name="p"/>'s kind: the quantised point lies in it.</summary>
    internal static bool Inside(SceneGeometry geometry, int p, int x, int y, int z) => geometry.KindOf(p).Inside(p, x, y, z);

    public static RayTable Build(SceneGeometry geometry, Ray ray)
    {
        ArgumentNullException.ThrowIfNull(geometry);
        return new RayTable(geometry, ray);
    }

    /// <summary>
    /// The compact table (<see cref="Compact"/>) built in one pass over the primitives, without the full table's
    /// N-row arrays: the same rows, depths, distances and <see cref="DepthBits"/> as <c>Build(…).Compact()</c>.
    /// </summary>
    public static RayTable BuildCompact(SceneGeometry geometry, Ray ray)
    {
        ArgumentNullException.ThrowIfNull(geometry);
        // It runs for every ray of every pass: the rows go into per-thread scratch, then into one array of their exact size.
        var n = geometry.Count;
        if (_scratch is null || _scratch.Length < n) _scratch = new KeptRow[n];
        var (count, maxDepth) = (0, 0);
        foreach (var kind in geometry.Kinds) kind.AppendInside(ray, _scratch, ref count, ref maxDepth);
        return new RayTable(geometry, ray, Math.Max(1, 32 - int.LeadingZeroCount(maxDepth)), _scratch.AsSpan(0, count).ToArray());
    }

    [ThreadStatic] private static KeptRow[]? _scratch;

    public SceneGeometry Geometry { get; }

    public Ray Ray { get; }

    /// <summary>N, one row per primitive.</summary>
    public int Count { get; }

    /// <summary>Whether this table holds only the rows inside their rectangles (see <see cref="Compact"/>).</summary>
    public bool IsCompact => _kept is not null;

    /// <summary>
    /// The same table holding only the rows whose point lies inside their rectangle: what verify-rpc
    /// can accept under any window, a handful of rows instead of N.
    /// </summary>
    public RayTable Compact()
    {
        if (IsCompact) return this;
        var inside = Enumerable.Range(0, Count).Where(p => Verify(p, new HitWindow(0, int.MaxValue, int.MaxValue))).ToArray();
        return new RayTable(this, inside);
    }

    /// <summary>Qubits of a coordinate register: the grid's bits.</summary>
    public int CoordinateBits => Geometry.Grid.Bits;

    /// <summary>Qubits of the depth register: enough for the largest depth in this table, at least 1.</summary>
    public int DepthBits { get; }

    /// <summary>Whether row <paramref name="p"/> holds a ray/plane point at all.</summary>
    public bool IsValid(int p) => Full.Valid[p];

    /// <summary>The quantised ray/plane point's grid integer along <paramref name="axis"/> (0 for an invalid row).</summary>
    public int Point(int p, int axis) => Full.Valid[p] ? Full.Points[p * 3 + axis] : 0;

    /// <summary>Quantised depth along the ray's principal axis (0 for a row without a point or, compact, outside its rectangle).</summary>
    public int Depth(int p) => _kept is not null ? Kept(p) is var k and >= 0 ? _kept[k].Depth : 0 : _depths![p];

    /// <summary>The ray parameter t of the unquantised ray/plane point, for shading (0 where <see cref="Depth"/> is).</summary>
    public double Distance(int p) => _kept is not null ? Kept(p) is var k and >= 0 ? _kept[k].Distance : 0 : _distances![p];

    /// <summary>verify-rpc: the point lies in the rectangle on every axis and its (depth, id) in the window.</summary>
    public bool Verify(int p, HitWindow window)
    {
        if (_kept is not null) return Kept(p) is var k and >= 0 && window.Accepts(_kept[k].Depth, p);
        var (valid, points) = Full;
        return valid[p] && Inside(Geometry, p, points[p * 3], points[p * 3 + 1], points[p * 3 + 2]) && window.Accepts(_depths![p], p);
    }

    /// <summary>
    /// The brute-force answer: the smallest (depth, id) that verify-rpc accepts under <paramref name="window"/>, or null.
    /// A compact table reads only its rows (no other row can be accepted); a full one every row.
    /// </summary>
    public int? BestAccepted(HitWindow window)
    {
        int? best = null;
        var bestDepth = 0;
        if (_kept is not null)
        {
            // Rows ascend, so the first of equal depths has the smaller id.
            foreach (var (p, depth, _) in _kept)
                if (window.Accepts(depth, p) && (best is null || depth < bestDepth)) (best, bestDepth) = (p, depth);
            return best;
        }
        var depths = _depths!;
        for (var p = 0; p < Count; p++)
            if (Verify(p, window) && (best is null || depths[p] < bestDepth)) (best, bestDepth) = (p, depths[p]);
        return best;
    }

    /// <summary>The oracle's marked set for <paramref name="window"/>: every row verify-rpc accepts.</summary>
    public MarkedSet Marked(HitWindow window)
    {
        if (_kept is null) return new MarkedSet(Count, Enumerable.Range(0, Count).Where(p => Verify(p, window)));
        // A compact table's rows ascend: the accepted ones are the set as it is, without a list or a sort.
        var accepted = 0;
        foreach (var (p, depth, _) in _kept)
            if (window.Accepts(depth, p)) accepted++;
        var marked = new int[accepted];
        accepted = 0;
        foreach (var (p, depth, _) in _kept)
            if (window.Accepts(depth, p)) marked[accepted++] = p;
        return MarkedSet.FromAscending(Count, marked);
    }

    private (bool[] Valid, int[] Points) Full => _valid is not null && _points is not null
        ? (_valid, _points)
        : throw new InvalidOperationException("a compact table holds only the rows inside their rectangles; build the full table");

    // Index of row p among a compact table's rows (ascending), −1 when it does not hold it.
    private int Kept(int p)
    {
        var (low, high) = (0, _kept!.Length - 1);
        while (low <= high)
        {
            var middle = (low + high) >>> 1;
            if (_kept[middle].Primitive == p) return middle;
            (low, high) = _kept[middle].Primitive < p ? (middle + 1, high) : (low, middle - 1);
        }
        return -1;
    }

    /// <summary>The window of this ray's own depth range.</summary>
    public HitWindow FullRange => HitWindow.Range(Ray.Near, Ray.Far, Count);

    /// <summary>The grid integer of a world value: floor(value · scale + tolerance), saturated to the int range.</summary>
    public static int Quantise(double value, double scale)
    {
        var scaled = Math.Floor(value * scale + SnapTolerance);
        return scaled >= int.MaxValue ? int.MaxValue : scaled <= int.MinValue ? int.MinValue : (int)scaled;
    }
}
