using QuantumRayTracing.Search;

namespace QuantumRayTracing.Passes;

/// <summary>
/// Never more than brute force: before a round, a ray whose remaining quantum work is expected to cost more than the
/// N tests that settle it is settled classically: it tests every primitive, counts N in #C_Int and its answer is
/// certain. The remaining work is the empty searches the stop rule or the budget still asks of it (for a ray nobody
/// vouches for, the misses that would keep the coarsest lattice within the budget) and, for a closest-hit ray
/// whose last search found something (or that has none yet), the search that may find a closer one first, each at
/// the engine's expected cost of an empty search (a search that finds stops sooner). Engines that cannot miss are
/// never settled: their search already is the classical answer.
/// </summary>
public static class ClassicalSettle
{
    // The reduction of a ray's odds of being wrong that budget rounds typically ask for.
    private const double Tenfold = 0.1;

    /// <param name="options">The pass's options: the rule applies when <see cref="PassOptions.Settle"/> is set.</param>
    /// <param name="search">The engine, for the expected cost of an empty search.</param>
    /// <param name="count">N, the tests that settle a ray.</param>
    /// <param name="worstMiss">A schedule's worst miss: an engine that cannot miss is never settled.</param>
    /// <param name="schedule">The schedule of ray i's search in a round.</param>
    /// <param name="misses">Ray i's consecutive empty searches so far.</param>
    /// <param name="vouched">Whether ray i's lattice neighbours vouch for it (one search may then end it).</param>
    /// <param name="findEnds">Whether a find ends the ray (visibility) rather than start a search for a closer hit.</param>
    public static Func<int, int, bool>? Rule(PassOptions options, IHitSearch search, int count, Func<QSearchSchedule?, double> worstMiss,
        Func<int, int, QSearchSchedule?> schedule, Func<int, int> misses, Func<int, bool> vouched, bool findEnds)
    {
        if (!options.Settle) return null;
        return (round, i) =>
        {
            var plan = schedule(round, i);
            if (worstMiss(plan) <= 0) return false;
            var required = vouched(i) ? 1 : options.Stop?.BudgetMisses ?? options.Iterations - round;
            var searches = Math.Max(1, required - misses(i)) + (!findEnds && misses(i) == 0 ? 1 : 0);
            return searches * search.EmptySearchCost(count, plan) > count;
        };
    }

    /// <summary>
    /// Whether even the cheapest ray of a pass would be settled before its first search: one confirmation with the
    /// lattice's cheap schedule where neighbours vouch (and, for a closest-hit ray, the search that finds its hit), else
    /// the full search; or, with an allowance, when lowering a ray's odds of being wrong tenfold, at the best rate a
    /// confirmation lowers them, costs more than N (an engine whose searches miss often, as the randomized one's
    /// floor(sqrt N) tests do). The whole pass is then settled outright, without the lattice's neighbour tests first.
    /// </summary>
    /// <param name="options">The pass's options: its lattice, stop rule, schedule and allowance.</param>
    /// <param name="search">The engine.</param>
    /// <param name="count">N, the tests that settle a ray.</param>
    /// <param name="rays">The pass's rays, among which its allowance is shared.</param>
    /// <param name="worstMiss">A schedule's worst miss: an engine that cannot miss is never settled.</param>
    /// <param name="findEnds">Whether a find ends a ray (visibility) rather than start a search for a closer hit.</param>
    public static bool SettlesEveryRay(PassOptions options, IHitSearch search, int count, int rays, Func<QSearchSchedule?, double> worstMiss, bool findEnds)
    {
        if (!options.Settle || worstMiss(options.Schedule) <= 0) return false;
        var cheapest = options.Lattice?.Agreed is { } agreed
            ? Math.Min(search.EmptySearchCost(count, agreed), search.EmptySearchCost(count, options.Schedule))
            : search.EmptySearchCost(count, options.Schedule);
        var searches = options.Lattice is null ? Math.Max(1, options.Stop?.BudgetMisses ?? options.Iterations) : 1;
        if ((searches + (findEnds ? 0 : 1)) * cheapest > count) return true;
        if (options.Allowance is null) return false;
        var best = BudgetRounds.Cheapest(search, count, options.Schedule, options.Lattice?.Agreed);
        var miss = worstMiss(best);
        return miss >= 1 || Math.Log(Tenfold) / Math.Log(miss) * search.EmptySearchCost(count, best) > count;
    }
}
