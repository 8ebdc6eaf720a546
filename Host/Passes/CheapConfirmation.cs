using System.Collections.Concurrent;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Passes;

/// <summary>
/// The lattice's cheap confirmation of a ray whose coarser neighbours agree, sized level by level by the pass's
/// allowance: its one search checks that nothing is closer than the agreed hit (for a shadow ray, that nothing
/// occludes), so it mostly finds nothing and its cost is that of an empty search, set by the miss it may have, not by
/// how many primitives it would find. Each level takes the planned list of least expected cost per ray, its own plus
/// what the budget rounds would still spend on the ray (<see cref="For"/>); without an allowance (or when the plan fixes
/// it) every level takes the plan's fixed list (<see cref="First"/>).
/// </summary>
public sealed class CheapConfirmation
{
    /// <summary>The miss bounds of the planned lists a level may take.</summary>
    public static readonly double[] Misses = [0.9, 0.8, 0.7, 0.6, 0.5, 0.4, 0.3, 0.2, 0.15, 0.1, 0.05, 0.025, 0.01];

    private static readonly ConcurrentDictionary<int, QSearchSchedule[]> Planned = new();

    private readonly (QSearchSchedule Schedule, double Miss, double Cost)[] _ladder;
    private readonly HashSet<QSearchSchedule> _schedules;
    private readonly double _roundRate;
    private readonly IHitSearch _search;
    private readonly int _count;

    /// <param name="first">The plan's fixed list, for the first level and for a pass without an allowance.</param>
    /// <param name="sized">Whether finer levels are sized by the allowance.</param>
    /// <param name="search">The engine, for each list's cost and worst miss.</param>
    /// <param name="count">N.</param>
    /// <param name="full">The pass's full schedule (null: the engine's own), one of the budget rounds' choices.</param>
    public CheapConfirmation(QSearchSchedule first, bool sized, IHitSearch search, int count, QSearchSchedule? full)
    {
        First = first;
        (_search, _count) = (search, count);
        var round = BudgetRounds.Cheapest(search, count, full, first);
        _roundRate = -Math.Log(Math.Max(1e-12, ConfirmationPlanner.WorstMiss(search, count, round))) / search.EmptySearchCost(count, round);
        var lists = sized ? Planned.GetOrAdd(count, n => [.. Misses
            .Select(m => ConfirmationPlanner.Cheapest(n, ConfirmationPlanner.MaxT, m)).OfType<QSearchSchedule>()]) : [];
        _ladder = [.. lists.Select(s => (s, ConfirmationPlanner.WorstMiss(search, count, s), search.EmptySearchCost(count, s)))
            .OrderBy(l => l.Item3).ThenBy(l => l.Item2)];
        _schedules = [first, .. lists];
    }

    /// <summary>
    /// The cheap confirmation of a pass with <paramref name="options"/>: null without a lattice or its cheap list; sized when the
    /// lattice plan asks for it and the pass has an allowance.
    /// </summary>
    public static CheapConfirmation? Of(PassOptions options, IHitSearch search, int count) =>
        options.Lattice is { Agreed: { } first } lattice ? new(first, lattice.Sized && options.Allowance is not null, search, count, options.Schedule) : null;

    /// <summary>Each ray's lattice level under <paramref name="options"/>, for the ledger's strata; null without a lattice.</summary>
    public static int[]? Levels(PassOptions options, int rays) =>
        options.Lattice is { } lattice && options.Neighbours is { } layout
            ? [.. Enumerable.Range(0, rays).Select(i => layout.LatticeLevel(i, lattice.Levels))]
            : null;

    /// <summary>The plan's fixed list.</summary>
    public QSearchSchedule First { get; }

    /// <summary>Whether <paramref name="schedule"/> is one of this confirmation's lists (its rays are on the cheap path).</summary>
    public bool Contains(QSearchSchedule? schedule) => schedule is not null && _schedules.Contains(schedule);

    /// <summary>
    /// The list for a lattice level whose <paramref name="rays"/> agreeing rays it confirms: <see cref="First"/> without a
    /// <paramref name="share"/> (no allowance), else the one of least expected cost per ray. A list costs its empty search;
    /// where it would leave a ray above its share, the budget rounds' cost of bringing the ray's odds down the rest of the way
    /// is added, ln(q / share) over the rounds' best rate of ln-odds per query (per ray, a pooled search's over the level's
    /// rays where the engine pools them and that is better). q = π w / (1 − π + π w) is what the ledger
    /// will charge a ray of the level, π its estimate of how often the level's neighbours mislead, which is not known before
    /// the level is searched: the cost is averaged over two guesses, that they never do (π is then the ledger's floor, half a
    /// find over the level's rays, ½ / ((rays + 1)(1 − w))) and that they do half as often as the next coarser level's did
    /// (<paramref name="coarser"/>, its neighbours being twice as far). The rounds buy down what the level's finds show.
    /// </summary>
    public QSearchSchedule For(int rays, double? share, double? coarser = null)
    {
        if (share is not { } s || s <= 0 || _ladder.Length == 0) return First;
        var rate = RoundRate(rays);
        double Cost(double miss, double cost, double estimate)
        {
            var pi = Math.Min(RayLedger.PriorCap, Math.Max(estimate, 0.5 / ((rays + 1) * (1 - miss))));
            var q = pi * miss / (1 - pi + pi * miss);
            return cost + (q > s && rate > 0 ? Math.Log(q / s) / rate : 0);
        }
        double Expected(double miss, double cost) => coarser is { } c
            ? (Cost(miss, cost, 0) + Cost(miss, cost, c / 2)) / 2
            : Cost(miss, cost, 0);
        return _ladder.MinBy(l => Expected(l.Miss, l.Cost)).Schedule;
    }

    // The budget rounds' best rate of ln-odds per query and ray: one ray's confirmation, or, on an engine that pools rays, a
    // pooled search over the level's rays, which lowers every ray's odds for the cost of one search about √rays times dearer.
    private double RoundRate(int rays)
    {
        if (_search is not IPooledSearch { PoolsRays: true } pooled || rays < 1) return _roundRate;
        var schedule = pooled.PooledSchedule(Math.Min(rays, PooledRound.PoolSize(_count)), _count);
        var miss = ConfirmationPlanner.WorstMiss(_search, _count, schedule);
        return Math.Max(_roundRate, -Math.Log(Math.Max(1e-12, miss)) * schedule.Count / _count / _search.EmptySearchCost(_count, schedule));
    }
}
