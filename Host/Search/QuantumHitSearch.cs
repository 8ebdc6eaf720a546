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
/// instead of the ideal one.
/// </summary>
public sealed class QuantumHitSearch(IGroverEngine engine, SeededRandom random, QSearchOptions options, bool gateLevel = false, FalseNegativeRate.RunSuccess? success = null) : IHitSearch
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

    public double MissProbability(int count, IReadOnlyList<double> pt, bool paperFormula, QSearchSchedule? schedule = null) =>
        paperFormula && schedule is null
            ? FalseNegativeRate.Eq10AtBound(Schedule(count), pt)
            : FalseNegativeRate.QSearchExact(schedule ?? Schedule(count), pt, success);

    public double EmptySearchCost(int count, QSearchSchedule? schedule = null) => SearchCost.ExpectedEmpty(schedule ?? Schedule(count));

    private QSearchSchedule Schedule(int count)
    {
        if (!_schedules.TryGetValue(count, out var schedule))
            _schedules[count] = schedule = new QSearchSchedule(count, options.Growth, options.Rule);
        return schedule;
    }

    public void Dispose() => engine.Dispose();
}
