using QuantumRayTracing.Search;

namespace QuantumRayTracing.Passes;

/// <summary>
/// Never more than brute force: before a round, a ray whose remaining quantum work (the empty searches the stop
/// rule still requires of it, at the engine's expected cost of an empty search) is expected to cost more than the
/// N tests that settle it is settled classically: it tests every primitive, counts N in #C_Int and its answer is
/// certain. Engines that cannot miss are never settled: their search already is the classical answer.
/// </summary>
public static class ClassicalSettle
{
    /// <param name="options">The pass's options: the rule applies when <see cref="PassOptions.Settle"/> is set.</param>
    /// <param name="search">The engine, for the expected cost of an empty search.</param>
    /// <param name="count">N, the tests that settle a ray.</param>
    /// <param name="worstMiss">A schedule's worst miss: an engine that cannot miss is never settled.</param>
    /// <param name="schedule">The schedule of ray i's search in a round.</param>
    /// <param name="misses">Ray i's consecutive empty searches so far.</param>
    /// <param name="vouched">Whether ray i's lattice neighbours vouch for it (one search may then end it).</param>
    public static Func<int, int, bool>? Rule(PassOptions options, IHitSearch search, int count, Func<QSearchSchedule?, double> worstMiss,
        Func<int, int, QSearchSchedule?> schedule, Func<int, int> misses, Func<int, bool> vouched)
    {
        if (!options.Settle) return null;
        return (round, i) =>
        {
            var plan = schedule(round, i);
            if (worstMiss(plan) <= 0) return false;
            var required = vouched(i) ? 1 : options.Stop?.RequiredMisses ?? options.Iterations - round;
            return Math.Max(1, required - misses(i)) * search.EmptySearchCost(count, plan) > count;
        };
    }
}
