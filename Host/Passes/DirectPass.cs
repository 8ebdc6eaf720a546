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
/// With an allowance, budget rounds follow until the rays' expected wrong is within it (<see cref="BudgetRounds"/>).
/// </summary>
public static class DirectPass
{
    public const int DefaultIterations = 2;

    public static (bool[] Occluded, PassMetrics Metrics) Run(
        string name, IHitSearch search, SceneGeometry geometry, IReadOnlyList<Ray> shadowRays, PassOptions options,
        IRenderProgress? progress = null)
    {
        var goal = new AnyOccluder(geometry, shadowRays);
        var metrics = SearchPass.Run(name, search, geometry, shadowRays, options, goal, progress);
        return ([.. goal.Occluders.Select(o => o is not null)], metrics);
    }

    /// <summary>Any occluder in the shadow ray's range: every search takes the full range, and a find ends the ray.</summary>
    private sealed class AnyOccluder(SceneGeometry geometry, IReadOnlyList<Ray> rays) : ISearchGoal
    {
        public int?[] Occluders { get; } = WrittenArray.Of<int?>(rays.Count);

        public bool FindEnds => true;

        public Func<int, bool>? Found => ray => Occluders[ray] is not null;

        public HitWindow Window(int ray, RayTable table) => table.FullRange;

        public void Apply(int ray, RayTable table, HitOutcome outcome) => Occluders[ray] ??= outcome.Primitive;

        public (long Tests, long Updated) Gather(PixelLayout layout) => NeighbourGathering.ForOcclusion(geometry, rays, Occluders, layout);

        public (long Tests, long Updated) FromLattice(int[] levelRays, PixelLayout layout, int levels, bool[] agreed) =>
            NeighbourGathering.FromLatticeOccluders(geometry, rays, levelRays, Occluders, layout, levels, agreed);
    }
}
