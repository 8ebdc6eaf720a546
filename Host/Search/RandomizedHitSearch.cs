using QuantumRayTracing.Randomness;

namespace QuantumRayTracing.Search;

/// <summary>
/// The randomized classical intersection of the paper's sec. 6.3: tests the ray against
/// floor(sqrt N) primitives drawn without replacement and returns the first accepted one among them
/// in the (depth, id) order. Certain only when it tested all N (N = 1).
/// </summary>
public sealed class RandomizedHitSearch(SeededRandom random) : IHitSearch
{
    public string Name => "randomized";

    public IReadOnlyList<HitOutcome> Run(IReadOnlyList<HitQuery> queries, Action<int, int>? onRound = null)
    {
        var outcomes = new HitOutcome[queries.Count];
        for (var k = 0; k < queries.Count; k++)
        {
            var (table, window, _) = queries[k];
            var tested = SampleSize(table.Count);
            outcomes[k] = new HitOutcome(BestAccepted.Among(table, window, Sample(table.Count, tested)), tested == table.Count,
                new SearchCost(0, 0, tested, 0));
        }
        onRound?.Invoke(1, 0);
        return outcomes;
    }

    /// <summary>floor(sqrt N), at least 1.</summary>
    public static int SampleSize(int count) => Math.Max(1, (int)Math.Floor(Math.Sqrt(count)));

    // The first `size` entries of a partial Fisher–Yates shuffle: distinct, uniform, in draw order.
    private int[] Sample(int count, int size)
    {
        var order = Enumerable.Range(0, count).ToArray();
        for (var i = 0; i < size; i++)
        {
            var j = random.NextInt(i, count - 1);
            (order[i], order[j]) = (order[j], order[i]);
        }
        return order[..size];
    }

    /// <summary>
    /// Eq. 11's product, exact for drawing without replacement. The paper averages it over t uniform on
    /// 1..N − floor(sqrt N) (the t that allow a miss); asked for the paper's formula, so do we.
    /// </summary>
    public double MissProbability(int count, IReadOnlyList<double> pt, bool paperFormula, QSearchSchedule? schedule = null) =>
        FalseNegativeRate.Randomized(count, SampleSize(count),
            paperFormula ? FalseNegativeRate.Uniform(count, Math.Max(1, count - SampleSize(count))) : pt);

    /// <summary>floor(sqrt N) tests, found or not.</summary>
    public double EmptySearchCost(int count, QSearchSchedule? schedule = null) => SampleSize(count);

    public void Dispose() { }
}
