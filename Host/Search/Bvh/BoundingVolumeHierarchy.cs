using QuantumRayTracing.Intersection;

namespace QuantumRayTracing.Search.Bvh;

/// <summary>
/// A bounding-volume hierarchy over a scene's primitives: the spatial structure a classical renderer would use
/// (the ray tracing paper's sec. 2 leaves it out on purpose: O(log N) queries after an O(N log N) build).
/// Built top-down with the surface area heuristic over <see cref="Bins"/> centroid bins per axis, a box test and
/// a primitive test each costing 1, as they do in #C_Int.
/// </summary>
/// <remarks>
/// <see cref="BuildWork"/> counts the build the way traversal is counted, one unit per primitive box read:
/// every node reads its primitives' boxes once per axis to bin them and once more to partition them, so a
/// balanced build costs about 4 N log2 N.
/// </remarks>
public sealed class BoundingVolumeHierarchy
{
    public const int Bins = 16;

    /// <summary>A node with more primitives than this is split even when the SAH would keep it a leaf.</summary>
    public const int MaxLeafSize = 4;

    private readonly BoundingBox[] _boxes;
    private readonly List<BvhNode> _nodes = [];
    private readonly int[] _order;
    private long _work;

    private BoundingVolumeHierarchy(SceneGeometry geometry)
    {
        Geometry = geometry;
        _boxes = [.. Enumerable.Range(0, geometry.Count).Select(p => BoundingBox.Of(geometry.KindOf(p).Bounds(p)))];
        _order = [.. Enumerable.Range(0, geometry.Count)];
        if (geometry.Count > 0) Build(0, geometry.Count);
        Nodes = [.. _nodes];
        BuildWork = _work;
    }

    public static BoundingVolumeHierarchy Build(SceneGeometry geometry)
    {
        ArgumentNullException.ThrowIfNull(geometry);
        return new BoundingVolumeHierarchy(geometry);
    }

    public SceneGeometry Geometry { get; }

    /// <summary>The nodes, depth-first from the root at 0.</summary>
    public IReadOnlyList<BvhNode> Nodes { get; }

    /// <summary>Primitive ids in leaf order: a leaf holds <c>Primitives[First .. First + Count]</c>.</summary>
    public IReadOnlyList<int> Primitives => _order;

    /// <summary>Primitive box reads the build made (see remarks): its cost in #C_Int units.</summary>
    public long BuildWork { get; }

    private int Build(int first, int count)
    {
        var index = _nodes.Count;
        var bounds = BoundingBox.Empty;
        var centres = BoundingBox.Empty;
        for (var i = first; i < first + count; i++)
        {
            bounds = bounds.Union(_boxes[_order[i]]);
            var c = _boxes[_order[i]].Centre;
            centres = centres.Union(new BoundingBox(c, c));
        }
        _nodes.Add(default);
        var split = count > 1 ? BestSplit(first, count, bounds, centres) : null;
        if (split is not { } s || (count <= MaxLeafSize && s.Cost >= count))
        {
            _nodes[index] = new BvhNode(bounds, first, count, 0, 0);
            return index;
        }
        var middle = Partition(first, count, s.Axis, s.Bin, centres);
        Build(first, middle - first);
        var second = Build(middle, first + count - middle);
        _nodes[index] = new BvhNode(bounds, 0, 0, second, s.Axis);
        return index;
    }

    // The SAH: 1 for the box test of each child visit's parent, plus each side's primitives weighted by the
    // chance a ray through the parent enters that side's box. Null when every centroid coincides.
    private (int Axis, int Bin, double Cost)? BestSplit(int first, int count, BoundingBox bounds, BoundingBox centres)
    {
        (int Axis, int Bin, double Cost)? best = null;
        for (var axis = 0; axis < 3; axis++)
        {
            var extent = centres.Max[axis] - centres.Min[axis];
            _work += count;
            if (extent <= 0) continue;
            var binCount = new int[Bins];
            var binBounds = Enumerable.Repeat(BoundingBox.Empty, Bins).ToArray();
            for (var i = first; i < first + count; i++)
            {
                var b = BinOf(_boxes[_order[i]].Centre[axis], centres.Min[axis], extent);
                binCount[b]++;
                binBounds[b] = binBounds[b].Union(_boxes[_order[i]]);
            }
            for (var cut = 1; cut < Bins; cut++)
            {
                var (left, right) = (BoundingBox.Empty, BoundingBox.Empty);
                var (nLeft, nRight) = (0, 0);
                for (var b = 0; b < cut; b++) (left, nLeft) = (left.Union(binBounds[b]), nLeft + binCount[b]);
                for (var b = cut; b < Bins; b++) (right, nRight) = (right.Union(binBounds[b]), nRight + binCount[b]);
                if (nLeft == 0 || nRight == 0) continue;
                var cost = 1 + (left.Area * nLeft + right.Area * nRight) / Math.Max(bounds.Area, double.Epsilon);
                if (best is null || cost < best.Value.Cost) best = (axis, cut, cost);
            }
        }
        return best;
    }

    private int Partition(int first, int count, int axis, int cut, BoundingBox centres)
    {
        _work += count;
        var extent = centres.Max[axis] - centres.Min[axis];
        var left = _order.AsSpan(first, count).ToArray().Where(p => BinOf(_boxes[p].Centre[axis], centres.Min[axis], extent) < cut).ToArray();
        var right = _order.AsSpan(first, count).ToArray().Where(p => BinOf(_boxes[p].Centre[axis], centres.Min[axis], extent) >= cut).ToArray();
        left.CopyTo(_order, first);
        right.CopyTo(_order, first + left.Length);
        return first + left.Length;
    }

    private static int BinOf(double centre, double min, double extent) =>
        Math.Min(Bins - 1, (int)(Bins * (centre - min) / extent));
}
