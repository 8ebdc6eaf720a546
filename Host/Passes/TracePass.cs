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
        var hits = WrittenArray.Of<Hit?>(rays.Count);
        bool[]? vouched = null; // the lattice's agreement flags, once lattice-first tracing runs
        var misses = new int[rays.Count];
        var worstMiss = RayLedger.WorstMisses(search, geometry.Count);
        var cheap = CheapConfirmation.Of(options, search, geometry.Count);
        var ledger = new RayLedger(rays.Count, worstMiss, cheap, findEnds: false, CheapConfirmation.Levels(options, rays.Count),
            RayLedger.WorstMisses(search, geometry.Count, machine: true));
        // The table's own ray: a pass's rays may be computed on each read.
        HitWindow Window(int i, RayTable table) =>
            Hit.Beyond(table.Ray, hits[i], table.Count, options.TieBreak);
        void Apply(int i, RayTable table, HitOutcome outcome)
        {
            if (outcome.Primitive is { } p) hits[i] = Hit.From(table, p);
        }
        bool Observe(int i, RayTable table, HitOutcome outcome)
        {
            Apply(i, table, outcome);
            misses[i] = outcome.Primitive is null ? misses[i] + 1 : 0;
            return outcome.Certain || options.Stop?.Continue(misses[i], vouched?[i] == true) == false;
        }
        Func<(long, long)>? gather = options.Neighbours is { } neighbours
            ? () => NeighbourGathering.ForClosest(geometry, rays, hits, neighbours, options.TieBreak)
            : null;
        Func<int, int, QSearchSchedule?> schedule = (_, _) => options.Schedule;
        var settle = ClassicalSettle.Rule(options, search, geometry.Count, worstMiss, (round, i) => schedule(round, i), i => misses[i],
            i => vouched?[i] == true, findEnds: false);

        PassMetrics metrics;
        if (ClassicalSettle.SettlesEveryRay(options, search, geometry.Count, rays.Count, worstMiss, findEnds: false))
            metrics = IteratedSearch.Run(name, search, geometry, rays, 1, Window, Observe, progress, ledger: ledger, settle: (_, _) => true);
        else if (options.Lattice is not { } lattice || options.Neighbours is not { } layout)
            metrics = IteratedSearch.Run(name, search, geometry, rays, options.Iterations, Window, Observe, progress, gather,
                schedule: schedule, ledger: ledger, settle: settle);
        else
        {
            QSearchSchedule? levelCheap = null;
            schedule = (round, i) => round == 0 && vouched![i] ? levelCheap : options.Schedule;
            metrics = LatticeOrder.Run(rays.Count, layout, lattice.Levels, progress, (level, levelRays, agreed, levelProgress) =>
            {
                vouched = agreed;
                var (tests, updated) = level == lattice.Levels ? (0L, 0L)
                    : NeighbourGathering.FromLattice(geometry, rays, levelRays, hits, layout, lattice.Levels, options.TieBreak, agreed);
                levelCheap = cheap?.For(levelRays.Count(i => agreed[i]), options.Allowance / Math.Max(1, rays.Count), ledger.CheapPrior(level + 1));
                var searched = IteratedSearch.Run(name, search, geometry, rays, options.Iterations, Window, Observe, levelProgress,
                    level == 0 ? gather : null, schedule: schedule, ledger: ledger, settle: settle, among: levelRays);
                return (searched, tests, updated);
            });
        }
        if (options.Allowance is { } allowance
            && BudgetRounds.Run(name, search, geometry, rays, ledger, allowance, options.Schedule, options.Lattice?.Agreed, Window, Apply) is { } rounds)
            metrics = PassMetrics.Phases(metrics, rounds with { RoundIntersections = rounds.IntersectionsConservative }, 0, 0);
        return (hits, metrics with { ExpectedWrong = ledger.MachineExpectedTotal, PlannedWrong = ledger.ExpectedTotal, CheapIntersections = ledger.CheapIntersections });
    }
}
