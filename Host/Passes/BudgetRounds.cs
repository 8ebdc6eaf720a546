using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Passes;

/// <summary>
/// Holds a pass to its share of the accuracy budget: while the rays' expected wrong (<see cref="RayLedger"/>)
/// exceeds the allowance, a round searches once more the fewest rays, most likely wrong first, whose
/// confirmation would bring it within: rays on the cheap path, rays whose trailing misses say little, rays
/// cut off by the round limit; but no ray less likely wrong than the likeliest will be after the round (that one's
/// next confirmation is the better buy, so rounds take the likeliest again before they reach the unlikely many). Each round uses the schedule that lowers a ray's odds of being wrong most per query
/// (the engine's full search, the lattice's cheap confirmation or a planned list). A ray whose remaining confirmations
/// are expected to cost more than the N tests that would settle it is settled classically instead. On an engine that
/// pools rays (<see cref="IPooledSearch"/>), a round searches the pairs of all the rays it needs at once instead
/// (<see cref="PooledRound"/>) when that costs less per expected wrong ray removed.
/// </summary>
public static class BudgetRounds
{
    /// <summary>Budget rounds at most; a pass still over its allowance after them says so.</summary>
    public const int MaxRounds = 8;

    /// <param name="name">The pass's name, for its metrics.</param>
    /// <param name="search">The engine.</param>
    /// <param name="geometry">The scene's primitives.</param>
    /// <param name="rays">The pass's rays.</param>
    /// <param name="ledger">The pass's record of its rays' searches, which the rounds extend.</param>
    /// <param name="allowance">The wrong rays the pass may leave, in expectation.</param>
    /// <param name="full">The schedule of a full search (null: the engine's own).</param>
    /// <param name="cheap">The lattice's cheap confirmation, or null.</param>
    /// <param name="window">The window of ray i's search, given its table.</param>
    /// <param name="apply">Takes a confirmation's outcome for a ray (a closer hit, an occluder).</param>
    public static PassMetrics? Run(
        string name, IHitSearch search, SceneGeometry geometry, IReadOnlyList<Ray> rays, RayLedger ledger, double allowance,
        QSearchSchedule? full, QSearchSchedule? cheap, Func<int, RayTable, HitWindow> window, Action<int, RayTable, HitOutcome> apply)
    {
        ledger.Freeze();
        var count = geometry.Count;
        var share = allowance / Math.Max(1, rays.Count);
        PassMetrics? total = null;
        for (var round = 0; round < MaxRounds; round++)
        {
            var expected = Enumerable.Range(0, rays.Count).Select(ledger.Expected).ToArray();
            var rest = expected.Sum();
            // Nothing left to buy (no rays, or none that may be wrong): a pass left no allowance by earlier passes stops here too.
            if (rest <= allowance || rest <= 0) break;
            var schedule = Cheapest(search, count, full, cheap);
            var miss = ConfirmationPlanner.WorstMiss(search, count, schedule);
            var cost = search.EmptySearchCost(count, schedule);
            var selected = new HashSet<int>();
            // A ray less likely wrong than the likeliest will still be after this round's confirmation waits: confirming
            // that one again next round buys more of the expectation per query. The last round takes what it needs.
            var floor = round == MaxRounds - 1 ? 0 : expected.Max() * miss;
            // Only rays at or above the floor can be taken: sorting just those keeps the round's memory to the few it may take.
            var left = rest;
            foreach (var i in Enumerable.Range(0, rays.Count).Where(i => expected[i] > 0 && expected[i] >= floor).OrderByDescending(i => expected[i]).ThenBy(i => i))
            {
                if (left <= allowance) break;
                selected.Add(i);
                left -= expected[i] * (1 - miss);
            }
            var price = selected.Count * cost / selected.Sum(i => expected[i] * (1 - miss));
            PassMetrics metrics;
            if (search is IPooledSearch { PoolsRays: true } pooled && Pool(search, pooled, count, expected, rest, allowance, price) is { } pool)
                metrics = PooledRound.Run(name, pooled, geometry, rays, pool, ledger, window, apply);
            else
            {
                var classically = selected.Where(i => SearchesToShare(expected[i], share, miss) * cost > count).ToHashSet();
                metrics = IteratedSearch.Run(name, search, geometry, rays, 1, window, (i, table, outcome) =>
                    {
                        apply(i, table, outcome);
                        return true;
                    }, progress: null, settled: i => !selected.Contains(i), schedule: (_, _) => schedule, ledger: ledger,
                    settle: (_, i) => classically.Contains(i));
            }
            total = total is null ? metrics : PassMetrics.Phases(total, metrics, 0, 0);
        }
        return total;
    }

    // The rays of a pooled round, likeliest wrong first until the rest is within the allowance: a pool's cost grows with
    // the root of its rays, so one round takes every ray it needs. Null when confirming rays one by one costs less per
    // expected wrong ray removed (price: the one-by-one round's queries per expected wrong ray it removes).
    private static List<int>? Pool(IHitSearch search, IPooledSearch pooled, int count, double[] expected, double rest, double allowance, double price)
    {
        var open = expected.Count(q => q > 0);
        var miss = ConfirmationPlanner.WorstMiss(search, count, pooled.PooledSchedule(Math.Min(open, PooledRound.PoolSize(count)), count));
        var chosen = new List<int>();
        var (removed, wrong) = (0.0, 0.0);
        foreach (var i in Enumerable.Range(0, expected.Length).Where(i => expected[i] > 0).OrderByDescending(i => expected[i]).ThenBy(i => i))
        {
            if (rest - removed <= allowance) break;
            chosen.Add(i);
            removed += expected[i] * (1 - miss);
            wrong += expected[i];
        }
        return removed > 0 && PooledRound.ExpectedCost(search, pooled, chosen.Count, count, wrong) / removed < price ? chosen : null;
    }

    // Confirmations that bring a ray's probability of being wrong from q to its share of the allowance, each
    // multiplying it by at most the schedule's worst miss; a search that cannot miss needs one.
    private static int SearchesToShare(double q, double share, double miss) =>
        q <= share ? 0 : miss <= 0 ? 1 : miss >= 1 ? int.MaxValue / 2 : (int)Math.Ceiling(Math.Log(share / q) / Math.Log(miss));

    /// <summary>The miss bounds of the planned confirmation lists a round may use besides the full search and the lattice's cheap one.</summary>
    public static readonly double[] PlannedMisses = [0.5, 0.3, 0.2, 0.1, 0.05];

    /// <summary>
    /// The schedule that lowers a ray's odds of being wrong most per expected query, −ln(worst miss) / cost of an empty
    /// search, among the full search, the lattice's cheap confirmation and the planned lists of <see cref="PlannedMisses"/>:
    /// a confirmation mostly finds nothing, so its empty cost is what it costs. (Choosing instead the list that just
    /// reaches the allowance in one round saved queries but, being weak, left more wrong pixels than the model expected.)
    /// </summary>
    public static QSearchSchedule? Cheapest(IHitSearch search, int count, QSearchSchedule? full, QSearchSchedule? cheap)
    {
        double Gain(QSearchSchedule? s) => -Math.Log(Math.Max(1e-12, ConfirmationPlanner.WorstMiss(search, count, s))) / search.EmptySearchCost(count, s);
        var best = full;
        var bestGain = Gain(full);
        IEnumerable<QSearchSchedule?> planned = PlannedMisses.Select(m => ConfirmationPlanner.Cheapest(count, ConfirmationPlanner.MaxT, m));
        foreach (var candidate in planned.Prepend(cheap).OfType<QSearchSchedule>())
            if (Gain(candidate) > bestGain) (best, bestGain) = (candidate, Gain(candidate));
        return best;
    }
}
