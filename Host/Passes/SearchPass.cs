using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Passes;

/// <summary>
/// The one driver of a pass of ray searches, for every <see cref="ISearchGoal"/>: rounds of searches (all rays, or with a lattice
/// plan the lattice levels coarsest first, each level's rays first testing their lattice neighbours' answers), each ray ending
/// when a find settles it, an engine's answer is certain or the stop rule ends it after a miss; rays whose remaining quantum
/// work would cost more than N classical tests settled classically; every search recorded in a <see cref="RayLedger"/>, and with
/// an allowance budget rounds until the rays' expected wrong is within it (<see cref="BudgetRounds"/>).
/// </summary>
public static class SearchPass
{
    public static PassMetrics Run(string name, IHitSearch search, SceneGeometry geometry, IReadOnlyList<Ray> rays, PassOptions options,
        ISearchGoal goal, IRenderProgress? progress = null)
    {
        bool[]? vouched = null; // the lattice's agreement flags, once lattice-first tracing runs
        var misses = new int[rays.Count];
        var findEnds = goal.FindEnds;
        var worstMiss = RayLedger.WorstMisses(search, geometry.Count);
        var cheap = CheapConfirmation.Of(options, search, geometry.Count);
        // The machine's misses are tracked apart only where they differ from the plan's (a noisy render planned as ideal).
        var ledger = new RayLedger(rays.Count, worstMiss, cheap, findEnds, CheapConfirmation.Levels(options, rays.Count),
            search.MachineMissesDiffer ? RayLedger.WorstMisses(search, geometry.Count, machine: true) : null);
        var found = goal.Found;
        bool Observe(int i, RayTable table, HitOutcome outcome)
        {
            goal.Apply(i, table, outcome);
            misses[i] = outcome.Primitive is null ? misses[i] + 1 : 0;
            return found?.Invoke(i) == true || outcome.Certain || options.Stop?.Continue(misses[i], vouched?[i] == true) == false;
        }
        Func<(long, long)>? gather = options.Neighbours is { } neighbours ? () => goal.Gather(neighbours) : null;
        Func<int, int, QSearchSchedule?> schedule = (_, _) => options.Schedule;
        var settle = ClassicalSettle.Rule(options, search, geometry.Count, worstMiss, (round, i) => schedule(round, i), i => misses[i],
            i => vouched?[i] == true, findEnds);

        PassMetrics metrics;
        if (ClassicalSettle.SettlesEveryRay(options, search, geometry.Count, rays.Count, worstMiss, findEnds))
            metrics = IteratedSearch.Run(name, search, geometry, rays, 1, goal.Window, Observe, progress, ledger: ledger, settle: (_, _) => true);
        else if (options.Lattice is not { } lattice || options.Neighbours is not { } layout)
            metrics = IteratedSearch.Run(name, search, geometry, rays, options.Iterations, goal.Window, Observe, progress, gather,
                settled: found, schedule: schedule, ledger: ledger, settle: settle);
        else
        {
            QSearchSchedule? levelCheap = null;
            schedule = (round, i) => round == 0 && vouched![i] ? levelCheap : options.Schedule;
            metrics = LatticeOrder.Run(rays.Count, layout, lattice.Levels, progress, (level, levelRays, agreed, levelProgress) =>
            {
                vouched = agreed;
                var (tests, updated) = level == lattice.Levels ? (0L, 0L) : goal.FromLattice(levelRays, layout, lattice.Levels, agreed);
                levelCheap = cheap?.For(levelRays.Count(i => agreed[i]), options.Allowance / Math.Max(1, rays.Count), ledger.CheapPrior(level + 1));
                var searched = IteratedSearch.Run(name, search, geometry, rays, options.Iterations, goal.Window, Observe, levelProgress,
                    level == 0 ? gather : null, settled: found, schedule: schedule, ledger: ledger, settle: settle, among: levelRays);
                return (searched, tests, updated);
            });
        }
        // A find a neighbour's ray lent is verified: the ray is not wrong, whatever its searches missed.
        if (found is not null)
            for (var i = 0; i < rays.Count; i++)
                if (found(i)) ledger.MarkCertain(i);
        if (options.Allowance is { } allowance
            && BudgetRounds.Run(name, search, geometry, rays, ledger, allowance, options.Schedule, options.Lattice?.Agreed, goal.Window, goal.Apply) is { } rounds)
            metrics = PassMetrics.Phases(metrics, rounds with { RoundIntersections = rounds.IntersectionsConservative }, 0, 0);
        return metrics with { ExpectedWrong = ledger.MachineExpectedTotal, PlannedWrong = ledger.ExpectedTotal, CheapIntersections = ledger.CheapIntersections };
    }
}
