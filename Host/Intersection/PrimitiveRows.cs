using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Intersection;

/// <summary>
/// The primitive seam: the primitives of one kind, ids <see cref="First"/> .. First + <see cref="Count"/> − 1 of a
/// scene, as a ray's lookup table and the classical tests see them on the scene's fixed-point grid. A kind gives its
/// table row (eval-rpc), its shape test on the row (verify-rpc without the window), the rows of every primitive at
/// once (the vectorised kernel), and the box a BVH bounds it with. One file per kind: <see cref="RectangleRows"/>,
/// <see cref="TriangleRows"/>; <see cref="For"/> is where a kind is registered.
/// </summary>
/// <remarks>
/// Every kind follows the same depth and tie rule: a row's depth is quantised along the ray's principal axis in grid
/// units, and the search orders hits by (depth, id) (docs/conventions.md). A kind's shape test must not leave cracks:
/// primitives sharing an edge or a corner claim each ray through it once, neither missing it nor both taking it.
/// </remarks>
public abstract class PrimitiveRows(CoordinateGrid grid, int first, int count)
{
    public CoordinateGrid Grid { get; } = grid;

    /// <summary>The scene id of this kind's first primitive.</summary>
    public int First { get; } = first;

    /// <summary>How many primitives of this kind follow from <see cref="First"/>.</summary>
    public int Count { get; } = count;

    /// <summary>Scale from world units to grid integers: 2^FractionBits.</summary>
    public double Scale => 1 << Grid.FractionBits;

    /// <summary>The rows for a run of primitives of one kind, ids <paramref name="first"/> on.</summary>
    public static PrimitiveRows For(CoordinateGrid grid, int first, IReadOnlyList<Primitive> run) => run[0] switch
    {
        Rectangle => new RectangleRows(grid, first, [.. run.Cast<Rectangle>()]),
        Triangle => new TriangleRows(grid, first, [.. run.Cast<Triangle>()]),
        _ => throw new ArgumentException($"no classical test for a {run[0].GetType().Name}", nameof(run)),
    };

    /// <summary>eval-rpc for primitive <paramref name="p"/> (a scene id of this kind) alone, O(1).</summary>
    public abstract TableRow Row(Ray ray, int p);

    /// <summary>verify-rpc's shape test on a valid row's quantised point: whether the ray hits the primitive there.</summary>
    public abstract bool Inside(int p, int x, int y, int z);

    /// <summary>
    /// Appends the rows of this kind whose point is inside their primitive, in ascending id, to <paramref name="rows"/>
    /// from <paramref name="count"/>, and raises <paramref name="maxDepth"/> to the largest depth of a valid row: the
    /// same rows as <see cref="Row"/> and <see cref="Inside"/> one by one.
    /// </summary>
    public virtual void AppendInside(Ray ray, Span<RayTable.KeptRow> rows, ref int count, ref int maxDepth) =>
        AppendInside(ray, First, rows, ref count, ref maxDepth);

    /// <summary>A world box holding every point at which <see cref="Row"/> can accept a ray: what a BVH node bounds.</summary>
    public abstract (Vec3 Min, Vec3 Max) Bounds(int p);

    /// <summary><see cref="AppendInside(Ray, Span{RayTable.KeptRow}, ref int, ref int)"/> one row at a time, from id <paramref name="from"/>.</summary>
    protected void AppendInside(Ray ray, int from, Span<RayTable.KeptRow> rows, ref int count, ref int maxDepth)
    {
        for (var p = from; p < First + Count; p++)
        {
            var row = Row(ray, p);
            if (!row.Valid) continue;
            maxDepth = Math.Max(maxDepth, row.Depth);
            if (!Inside(p, row.X, row.Y, row.Z)) continue;
            rows[count++] = new(p, row.Depth, row.Distance);
        }
    }
}
