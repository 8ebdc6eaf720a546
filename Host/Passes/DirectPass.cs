using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Passes;

/// <summary>
/// DirectPass (appendix B, Algorithm 6): light visibility. Each round runs QOccluded (any hit in the
/// shadow ray's range, no minimisation) for every shadow ray not yet found occluded; then, with a
/// layout, each unoccluded ray is tested against its neighbours' occluders. A ray is finished once
/// occluded, once an engine's answer is certain, or when the stop rule ends it after a miss. The paper
/// uses two rounds: the second catches most of QSearch's false negatives. With a lattice plan the
/// lattice rays go first and the others test their lattice neighbours' occluders before searching.
/// </summary>
public static class DirectPass
{
    public const int DefaultIterations = 2;

    public static (bool[] Occluded, PassMetrics Metrics) Run(
        string name, IHitSearch search, SceneGeometry geometry, IReadOnlyList<Ray> shadowRays, PassOptions options,
        IRenderProgress? progress = null)
    {
        var occluders = new int?[shadowRays.Count];
        bool[]? vouched = null; // the lattice's agreement flags, once lattice-first tracing runs
        var misses = new int[shadowRays.Count];
        bool Observe(int i, RayTable table, HitOutcome outcome)
        {
            occluders[i] ??= outcome.Primitive;
            misses[i] = outcome.Primitive is null ? misses[i] + 1 : 0;
            return occluders[i] is not null || outcome.Certain || options.Stop?.Continue(misses[i], vouched?[i] == true) == false;
        }
        Func<(long, long)>? gather = options.Neighbours is { } neighbours
            ? () => NeighbourGathering.ForOcclusion(geometry, shadowRays, occluders, neighbours)
            : null;
        static HitWindow Window(int i, RayTable table) => table.FullRange;

        if (options.Lattice is not { } lattice || options.Neighbours is not { } layout)
        {
            var metrics = IteratedSearch.Run(name, search, geometry, shadowRays, options.Iterations, Window, Observe, progress, gather,
                settled: i => occluders[i] is not null, schedule: (_, _) => options.Schedule);
            return ([.. occluders.Select(o => o is not null)], metrics);
        }

        var phased = LatticeOrder.Run(shadowRays.Count, layout, lattice.Levels, progress, (level, levelRays, agreed, levelProgress) =>
        {
            vouched = agreed;
            var inLevel = levelRays.ToHashSet();
            var (tests, updated) = level == lattice.Levels ? (0L, 0L)
                : NeighbourGathering.FromLatticeOccluders(geometry, shadowRays, levelRays, occluders, layout, lattice.Levels, agreed);
            var searched = IteratedSearch.Run(name, search, geometry, shadowRays, options.Iterations, Window, Observe, levelProgress,
                level == 0 ? gather : null, settled: i => occluders[i] is not null || !inLevel.Contains(i),
                schedule: (round, i) => round == 0 && agreed[i] ? lattice.Agreed : options.Schedule);
            return (searched, tests, updated);
        });
        return ([.. occluders.Select(o => o is not null)], phased);
    }
}
