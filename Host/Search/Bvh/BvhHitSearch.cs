using QuantumRayTracing.Intersection;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Search.Bvh;

/// <summary>
/// The classical renderer with a spatial structure: each ray walks a <see cref="BoundingVolumeHierarchy"/> front to
/// back and returns the best accepted primitive in the (depth, id) order, the same certain answer as brute force.
/// Its #C_Int counts every node box test and every primitive test, one each; the hierarchy is built once per
/// scene (once per frame, as for a dynamic scene) and its <see cref="BoundingVolumeHierarchy.BuildWork"/> is
/// charged to the first search that needs it.
/// </summary>
public sealed class BvhHitSearch : IHitSearch
{
    private readonly Lock _gate = new();
    private BoundingVolumeHierarchy? _hierarchy;

    public string Name => "bvh";

    /// <summary>The hierarchy of the scene searched last, null before the first search.</summary>
    public BoundingVolumeHierarchy? Hierarchy => _hierarchy;

    public IReadOnlyList<HitOutcome> Run(IReadOnlyList<HitQuery> queries, Action<int, int>? onRound = null)
    {
        var outcomes = new HitOutcome[queries.Count];
        if (queries.Count == 0) return outcomes;
        var (hierarchy, buildWork) = HierarchyFor(queries[0].Table.Geometry);
        Parallel.For(0, queries.Count, k =>
        {
            var (table, window, _) = queries[k];
            if (table.Geometry != hierarchy.Geometry) throw new ArgumentException("every query of a batch must search the same scene", nameof(queries));
            var (primitive, tests) = Search(hierarchy, table.Ray, window);
            outcomes[k] = new HitOutcome(primitive, true, new SearchCost(0, 0, tests, 0));
        });
        outcomes[0] = outcomes[0] with { Cost = outcomes[0].Cost + new SearchCost(0, 0, buildWork, 0) };
        onRound?.Invoke(1, 0);
        return outcomes;
    }

    /// <summary>
    /// One ray's walk: the best primitive <paramref name="window"/> accepts and the tests it took. A node is skipped
    /// when the ray misses its box, or when every depth inside it is past the window or past the best hit so far
    /// (depth grows with the ray parameter, so the box's entry point bounds it from below).
    /// </summary>
    public static (int? Primitive, long Tests) Search(BoundingVolumeHierarchy hierarchy, Rays.Ray ray, HitWindow window)
    {
        var geometry = hierarchy.Geometry;
        var (origin, direction) = (ray.Origin, ray.Direction);
        var inverse = new Vec3(1 / direction.X, 1 / direction.Y, 1 / direction.Z);
        var principal = Math.Max(Math.Abs(direction.X), Math.Max(Math.Abs(direction.Y), Math.Abs(direction.Z)));
        var (nodes, order) = (hierarchy.Nodes, hierarchy.Primitives);
        int? best = null;
        var bestDepth = 0;
        long tests = 0;
        // Each node is pushed at most once, so a stack of the node count never overflows; kept per thread, not per ray.
        if (_stack is null || _stack.Length < nodes.Count) _stack = new int[nodes.Count];
        var stack = _stack;
        var top = 0;
        if (nodes.Count > 0) stack[top++] = 0;
        while (top > 0)
        {
            var index = stack[--top];
            var node = nodes[index];
            tests++;
            if (node.Bounds.Clip(origin, inverse, 0, ray.MaxDistance) is not var (enter, exit)) continue;
            var nearest = RayTable.Quantise(enter * principal, geometry.Scale);
            if (nearest > window.LimitDepth || (best is not null && nearest > bestDepth)) continue;
            if (RayTable.Quantise(exit * principal, geometry.Scale) < window.Near) continue;
            if (node.IsLeaf)
            {
                for (var i = node.First; i < node.First + node.Count; i++)
                {
                    var p = order[i];
                    tests++;
                    if (RayTable.Test(geometry, ray, p, window) is not { } row) continue;
                    if (best is not { } b || row.Depth < bestDepth || (row.Depth == bestDepth && p < b)) (best, bestDepth) = (p, row.Depth);
                }
                continue;
            }
            // Front to back: the child on the side the ray comes from is walked first (pushed last).
            var (first, second) = (index + 1, node.SecondChild);
            if (direction[node.Axis] < 0) (first, second) = (second, first);
            stack[top++] = second;
            stack[top++] = first;
        }
        return (best, tests);
    }

    [ThreadStatic] private static int[]? _stack;

    /// <summary>None: every primitive the ray can hit is tested.</summary>
    public double MissProbability(int count, IReadOnlyList<double> pt, bool paperFormula, QSearchSchedule? schedule = null) => 0;

    /// <summary>N, what brute force would spend; a search that misses is never confirmed, its answer being certain.</summary>
    public double EmptySearchCost(int count, QSearchSchedule? schedule = null) => count;

    public void Dispose() { }

    // The hierarchy for a scene, and the build work to charge: nonzero only when this call built it.
    private (BoundingVolumeHierarchy Hierarchy, long BuildWork) HierarchyFor(SceneGeometry geometry)
    {
        lock (_gate)
        {
            if (_hierarchy?.Geometry == geometry) return (_hierarchy, 0);
            _hierarchy = BoundingVolumeHierarchy.Build(geometry);
            return (_hierarchy, _hierarchy.BuildWork);
        }
    }
}
