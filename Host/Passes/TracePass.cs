using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Passes;

/// <summary>
/// TracePass (Algorithm 4): minimum finding over depth for primary or specular rays. Each round
/// searches every unfinished ray for a hit closer than its current one (QTrace, Algorithm 3) and keeps
/// what it finds; then, with a layout, NeighOpt (Algorithm 5) tests each ray against its neighbours'
/// primitives. A ray is finished when the engine's answer is certain (the classical engines test every
/// primitive, so the classical reference costs one round) or when the stop rule ends it after a miss.
/// With a lattice plan the lattice rays go first and the others start from their lattice neighbours' hits.
/// With an allowance, budget rounds follow until the rays' expected wrong is within it (<see cref="BudgetRounds"/>).
/// </summary>
public static class TracePass
{
    public static (Hit?[] Hits, PassMetrics Metrics) Run(
        string name, IHitSearch search, SceneGeometry geometry, IReadOnlyList<Ray> rays, PassOptions options,
        IRenderProgress? progress = null)
    {
        var goal = new ClosestHit(geometry, rays, options.TieBreak);
        return (goal.Hits, SearchPass.Run(name, search, geometry, rays, options, goal, progress));
    }

    /// <summary>Each ray's closest hit: a search looks beyond the best so far, a find keeps the ray searching for a closer one.</summary>
    private sealed class ClosestHit(SceneGeometry geometry, IReadOnlyList<Ray> rays, TieBreak tieBreak) : ISearchGoal
    {
        public Hit?[] Hits { get; } = WrittenArray.Of<Hit?>(rays.Count);

        public bool FindEnds => false;

        public Func<int, bool>? Found => null;

        // The table's own ray: a pass's rays may be computed on each read.
        public HitWindow Window(int ray, RayTable table) => Hit.Beyond(table.Ray, Hits[ray], table.Count, tieBreak);

        public void Apply(int ray, RayTable table, HitOutcome outcome)
        {
            if (outcome.Primitive is { } p) Hits[ray] = Hit.From(table, p);
        }

        public (long Tests, long Updated) Gather(PixelLayout layout) => NeighbourGathering.ForClosest(geometry, rays, Hits, layout, tieBreak);

        public (long Tests, long Updated) FromLattice(int[] levelRays, PixelLayout layout, int levels, bool[] agreed) =>
            NeighbourGathering.FromLattice(geometry, rays, levelRays, Hits, layout, levels, tieBreak, agreed);
    }
}
