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
        var occluders = WrittenArray.Of<int?>(shadowRays.Count);
        bool[]? vouched = null; // the lattice's agreement flags, once lattice-first tracing runs
        var misses = new int[shadowRays.Count];
        var worstMiss = RayLedger.WorstMisses(search, geometry.Count);
        var cheap = CheapConfirmation.Of(options, search, geometry.Count);
        var ledger = new RayLedger(shadowRays.Count, worstMiss, cheap, findEnds: true, CheapConfirmation.Levels(options, shadowRays.Count),
            RayLedger.WorstMisses(search, geometry.Count, machine: true));
        void Apply(int i, RayTable table, HitOutcome outcome) => occluders[i] ??= outcome.Primitive;
        bool Observe(int i, RayTable table, HitOutcome outcome)
        {
            Apply(i, table, outcome);
            misses[i] = outcome.Primitive is null ? misses[i] + 1 : 0;
            return occluders[i] is not null || outcome.Certain || options.Stop?.Continue(misses[i], vouched?[i] == true) == false;
        }
        Func<(long, long)>? gather = options.Neighbours is { } neighbours
            ? () => NeighbourGathering.ForOcclusion(geometry, shadowRays, occluders, neighbours)
            : null;
        static HitWindow Window(int i, RayTable table) => table.FullRange;
        Func<int, int, QSearchSchedule?> schedule = (_, _) => options.Schedule;
        var settle = ClassicalSettle.Rule(options, search, geometry.Count, worstMiss, (round, i) => schedule(round, i), i => misses[i],
            i => vouched?[i] == true, findEnds: true);

        PassMetrics metrics;
        if (ClassicalSettle.SettlesEveryRay(options, search, geometry.Count, shadowRays.Count, worstMiss, findEnds: true))
            metrics = IteratedSearch.Run(name, search, geometry, shadowRays, 1, Window, Observe, progress, ledger: ledger, settle: (_, _) => true);
        else if (options.Lattice is not { } lattice || options.Neighbours is not { } layout)
            metrics = IteratedSearch.Run(name, search, geometry, shadowRays, options.Iterations, Window, Observe, progress, gather,
                settled: i => occluders[i] is not null, schedule: schedule, ledger: ledger, settle: settle);
        else
        {
            QSearchSchedule? levelCheap = null;
            schedule = (round, i) => round == 0 && vouched![i] ? levelCheap : options.Schedule;
            metrics = LatticeOrder.Run(shadowRays.Count, layout, lattice.Levels, progress, (level, levelRays, agreed, levelProgress) =>
            {
                vouched = agreed;
                var (tests, updated) = level == lattice.Levels ? (0L, 0L)
                    : NeighbourGathering.FromLatticeOccluders(geometry, shadowRays, levelRays, occluders, layout, lattice.Levels, agreed);
                levelCheap = cheap?.For(levelRays.Count(i => agreed[i]), options.Allowance / Math.Max(1, shadowRays.Count), ledger.CheapPrior(level + 1));
                var searched = IteratedSearch.Run(name, search, geometry, shadowRays, options.Iterations, Window, Observe, levelProgress,
                    level == 0 ? gather : null, settled: i => occluders[i] is not null, schedule: schedule,
                    ledger: ledger, settle: settle, among: levelRays);
                return (searched, tests, updated);
            });
        }
        // An occluder a neighbour's ray lent is verified: the ray is not wrong, whatever its searches missed.
        for (var i = 0; i < shadowRays.Count; i++)
            if (occluders[i] is not null) ledger.MarkCertain(i);
        if (options.Allowance is { } allowance
            && BudgetRounds.Run(name, search, geometry, shadowRays, ledger, allowance, options.Schedule, options.Lattice?.Agreed, Window, Apply) is { } rounds)
            metrics = PassMetrics.Phases(metrics, rounds with { RoundIntersections = rounds.IntersectionsConservative }, 0, 0);
        return ([.. occluders.Select(o => o is not null)], metrics with { ExpectedWrong = ledger.MachineExpectedTotal, PlannedWrong = ledger.ExpectedTotal, CheapIntersections = ledger.CheapIntersections });
    }
}
