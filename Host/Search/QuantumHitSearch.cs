using QuantumRayTracing.Engines;
using QuantumRayTracing.Randomness;

namespace QuantumRayTracing.Search;

/// <summary>
/// Ray searches by QSearch over a Grover engine (QTrace and QOccluded, Algorithm 3): the marked set is
/// the table's verify-rpc set, every search of a batch advances in lock step through
/// <see cref="QSearchDriver"/>. With <paramref name="gateLevel"/> each request also carries the table
/// and window, which the gate engine loads into its gate-level oracle (the full table: a compact one
/// kept between rounds is rebuilt for it). With <paramref name="success"/> the miss rates the passes plan with (termination
/// rule, lattice confirmations, accuracy budget, classical settling) take each run's success from it, a noisy machine's,
/// instead of the ideal one; <paramref name="machineSuccess"/>, when the machine's differs from the plan's, gives the miss rates the
/// expected wrong pixels are reported with. With <paramref name="pooled"/> it also runs pooled searches (<see cref="IPooledSearch"/>).
/// </summary>
public sealed class QuantumHitSearch(IGroverEngine engine, SeededRandom random, QSearchOptions options, bool gateLevel = false, FalseNegativeRate.RunSuccess? success = null,
    bool pooled = false, FalseNegativeRate.RunSuccess? machineSuccess = null) : IHitSearch, IPooledSearch
{
    private readonly Dictionary<int, QSearchSchedule> _schedules = [];

    public string Name => engine.Name;

    public IReadOnlyList<HitOutcome> Run(IReadOnlyList<HitQuery> queries, Action<int, int>? onRound = null)
    {
        var searches = new QSearch[queries.Count];
        var schedules = queries.Select(q => q.Table.Count).Distinct().ToDictionary(n => n, Schedule);
        // Marked sets are O(N) each and independent; no randomness is drawn before the driver runs.
        Parallel.For(0, queries.Count, k =>
        {
            var (table, window, schedule) = queries[k];
            searches[k] = new QSearch(table.Marked(window), schedule ?? schedules[table.Count], random,
                gateLevel ? new Intersection.OracleInput(table.IsCompact ? Intersection.RayTable.Build(table.Geometry, table.Ray) : table, window) : null);
        });
        QSearchDriver.Run(searches, engine, onRound);
        return searches.Select(s => new HitOutcome(s.Found, false, s.Cost)).ToArray();
    }

    public bool PoolsRays => pooled;

    public QSearchSchedule PooledSchedule(int rays, int count) => Schedule(checked(rays * count));

    public PooledOutcome RunPooled(IReadOnlyList<HitQuery> queries)
    {
        if (!pooled) throw new InvalidOperationException($"the {Name} engine does not run pooled searches");
        var count = queries[0].Table.Count;
        if (queries.Any(q => q.Table.Count != count)) throw new ArgumentException("a pooled search's tables share one N", nameof(queries));
        if ((long)queries.Count * count > IPooledSearch.MaxPairs)
            throw new ArgumentException($"{queries.Count} rays of {count} primitives exceed a pooled search's {IPooledSearch.MaxPairs} pairs", nameof(queries));
        // Pair (k, p) is index k·N + p: each table's accepted rows ascend, so the pool's marked pairs ascend as they are listed.
        var marked = new List<int>();
        for (var k = 0; k < queries.Count; k++)
            foreach (var p in queries[k].Table.Marked(queries[k].Window).Indices) marked.Add(k * count + p);
        var search = new QSearch(MarkedSet.FromAscending(queries.Count * count, [.. marked]), PooledSchedule(queries.Count, count), random);
        QSearchDriver.Run([search], engine);
        return search.Found is { } pair ? new PooledOutcome(pair / count, pair % count, search.Cost) : new PooledOutcome(null, null, search.Cost);
    }

    public double MissProbability(int count, IReadOnlyList<double> pt, bool paperFormula, QSearchSchedule? schedule = null) =>
        paperFormula && schedule is null
            ? FalseNegativeRate.Eq10AtBound(Schedule(count), pt)
            : FalseNegativeRate.QSearchExact(schedule ?? Schedule(count), pt, success);

    public bool MachineMissesDiffer => machineSuccess is not null && machineSuccess != success;

    public double MachineMissProbability(int count, IReadOnlyList<double> pt, QSearchSchedule? schedule = null) =>
        FalseNegativeRate.QSearchExact(schedule ?? Schedule(count), pt, machineSuccess ?? success);

    public double EmptySearchCost(int count, QSearchSchedule? schedule = null) => SearchCost.ExpectedEmpty(schedule ?? Schedule(count));

    private QSearchSchedule Schedule(int count)
    {
        if (!_schedules.TryGetValue(count, out var schedule))
            _schedules[count] = schedule = new QSearchSchedule(count, options.Growth, options.Rule);
        return schedule;
    }

    public void Dispose() => engine.Dispose();
}
