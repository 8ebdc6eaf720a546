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
        // The answers are kept in 12 bytes each and handed back as outcomes when read: a block's outcomes as an array are
        // 48 bytes each, allocated for every block of every pass.
        var answers = new Answer[queries.Count];
        Parallel.For(0, queries.Count, k =>
        {
            var (table, window, _) = queries[k];
            answers[k] = new Answer(table.BestAccepted(window), table.Count);
        });
        onRound?.Invoke(1, 0);
        return new Rays.ComputedList<HitOutcome>(answers.Length, k => new HitOutcome(answers[k].Primitive, true, new SearchCost(0, 0, answers[k].Tests, 0)));
    }

    private readonly record struct Answer(int? Primitive, int Tests);

    /// <summary>None: every primitive is tested.</summary>
    public double MissProbability(int count, IReadOnlyList<double> pt, bool paperFormula, QSearchSchedule? schedule = null) => 0;

    /// <summary>N: every primitive is tested.</summary>
    public double EmptySearchCost(int count, QSearchSchedule? schedule = null) => count;

    public void Dispose() { }
}
