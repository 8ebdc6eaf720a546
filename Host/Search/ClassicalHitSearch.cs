namespace QuantumRayTracing.Search;

/// <summary>
/// The brute-force reference: tests the ray against every primitive (N classical tests) and returns
/// the first accepted one in the (depth, id) order. Its answer is certain.
/// </summary>
public sealed class ClassicalHitSearch : IHitSearch
{
    public string Name => "classical";

    public IReadOnlyList<HitOutcome> Run(IReadOnlyList<HitQuery> queries, Action<int, int>? onRound = null)
    {
        var outcomes = new HitOutcome[queries.Count];
        Parallel.For(0, queries.Count, k =>
        {
            var (table, window, _) = queries[k];
            outcomes[k] = new HitOutcome(table.BestAccepted(window), true,
                new SearchCost(0, 0, table.Count, 0));
        });
        onRound?.Invoke(1, 0);
        return outcomes;
    }

    /// <summary>None: every primitive is tested.</summary>
    public double MissProbability(int count, IReadOnlyList<double> pt, bool paperFormula, QSearchSchedule? schedule = null) => 0;

    /// <summary>N: every primitive is tested.</summary>
    public double EmptySearchCost(int count, QSearchSchedule? schedule = null) => count;

    public void Dispose() { }
}
