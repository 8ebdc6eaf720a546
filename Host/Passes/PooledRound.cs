using System.Diagnostics;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Passes;

/// <summary>
/// A budget round by pooled searches (<see cref="IPooledSearch"/>): the chosen rays' (ray, primitive) pairs searched
/// together, in pools of at most <see cref="IPooledSearch.MaxPairs"/> pairs, until a search finds nothing. Each find is a
/// wrong ray put right (a closer hit taken, an occluder found) and its pool is searched again, the ray still in it while
/// it may have a closer hit. Only the empty search that ends a pool counts as a confirmation of its rays, lowering each
/// one's odds by the pooled schedule's worst miss: a search that found another ray's pair says nothing certain about the rest.
/// </summary>
public static class PooledRound
{
    /// <summary>The most rays one pool holds at <paramref name="count"/> primitives.</summary>
    public static int PoolSize(int count) => IPooledSearch.MaxPairs / count;

    /// <summary>The pools of <paramref name="rays"/> chosen rays, largest first.</summary>
    public static IEnumerable<int> Pools(int rays, int count)
    {
        for (var left = rays; left > 0; left -= PoolSize(count)) yield return Math.Min(left, PoolSize(count));
    }

    /// <summary>
    /// The expected #Int (conservative) of a round over <paramref name="rays"/> rays expected to hold <paramref name="wrong"/>
    /// wrong ones: each pool's empty search, and the searches that find them. With k pairs marked a find takes about
    /// 1/√k of an empty search, so finding K wrong rays one by one takes about Σ 1/√k ≈ 2√K empty searches.
    /// </summary>
    public static double ExpectedCost(IHitSearch search, IPooledSearch pooled, int rays, int count, double wrong) =>
        Pools(rays, count).Sum(size => search.EmptySearchCost(count, pooled.PooledSchedule(size, count))) * (1 + 2 * Math.Sqrt(wrong));

    /// <param name="name">The pass's name, for its metrics.</param>
    /// <param name="pooled">The engine's pooled search.</param>
    /// <param name="geometry">The scene's primitives.</param>
    /// <param name="rays">The pass's rays.</param>
    /// <param name="chosen">The rays to confirm, in pool order.</param>
    /// <param name="ledger">The pass's record of its rays' searches, which the round extends.</param>
    /// <param name="window">The window of ray i's search, given its table.</param>
    /// <param name="apply">Takes a find for a ray (a closer hit, an occluder).</param>
    public static PassMetrics Run(
        string name, IPooledSearch pooled, SceneGeometry geometry, IReadOnlyList<Ray> rays, IReadOnlyList<int> chosen, RayLedger ledger,
        Func<int, RayTable, HitWindow> window, Action<int, RayTable, HitOutcome> apply)
    {
        var clock = Stopwatch.StartNew();
        var count = geometry.Count;
        var cost = default(SearchCost);
        long tableRows = 0;
        var start = 0;
        foreach (var size in Pools(chosen.Count, count))
        {
            var pool = chosen.Skip(start).Take(size).ToList();
            start += size;
            var tables = pool.AsParallel().AsOrdered().Select(i => RayTable.BuildCompact(geometry, rays[i])).ToList();
            tableRows += (long)pool.Count * count;
            while (pool.Count > 0)
            {
                var schedule = pooled.PooledSchedule(pool.Count, count);
                var outcome = pooled.RunPooled([.. pool.Select((ray, k) => new HitQuery(tables[k], window(ray, tables[k])))]);
                cost += outcome.Cost;
                if (outcome is not { Query: { } k, Primitive: { } primitive })
                {
                    foreach (var ray in pool) ledger.Record(ray, schedule, new HitOutcome(null, false, default));
                    break;
                }
                var found = new HitOutcome(primitive, false, default);
                apply(pool[k], tables[k], found);
                ledger.Record(pool[k], schedule, found);
                // A ray the ledger no longer charges (an occluder found settles it) leaves the pool; after a closer hit it stays.
                if (ledger.Expected(pool[k]) > 0) continue;
                pool.RemoveAt(k);
                tables.RemoveAt(k);
            }
        }
        return new PassMetrics(name, rays.Count, 1, cost, tableRows, clock.Elapsed);
    }
}
