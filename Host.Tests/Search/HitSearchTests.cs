using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Statistics;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Search;

/// <summary>
/// The three searches behind <see cref="IHitSearch"/> on tables whose accepted rows are known by
/// construction: every ray here runs from (3.5, 3.5, 0) along +z and meets the planes at (3, 3, z),
/// so a rectangle spanning x, y in 0..8 is hit at depth z and one spanning 10..12 is missed.
/// </summary>
public class HitSearchTests
{
    private static readonly Ray Down = new(new Vec3(3.5, 3.5, 0), new Vec3(0, 0, 1));

    private static string Hit(int z) => Rect(0, 0, z, 8, 8, z);

    private static string Miss(int z) => Rect(10, 10, z, 12, 12, z);

    // Hit at depths: id 0 → 10, id 1 → 4, id 2 → 8, id 3 → 8 (tie with id 2); id 4 and 5 missed.
    private static readonly RayTable Stack = Table(With(4, 0, Hit(10), Hit(4), Hit(8), Hit(8), Miss(2), Miss(9)), Down);

    /// <summary>N rectangles; those listed in <paramref name="hits"/> (id → z) are hit, the others missed.</summary>
    private static RayTable Layered(int count, IReadOnlyDictionary<int, int> hits) =>
        Table(With(4, 0, Enumerable.Range(0, count).Select(p => hits.TryGetValue(p, out var z) ? Hit(z) : Miss(1 + p % 14))), Down);

    /// <summary>t accepted rows out of N, spread over the ids (7 is coprime to every N used), with repeated depths.</summary>
    private static RayTable Spread(int count, int accepted) =>
        Layered(count, Enumerable.Range(0, count).Where(p => p * 7 % count < accepted).ToDictionary(p => p, p => 2 + p % 5 * 2));

    private static double Choose(int n, int k)
    {
        if (k < 0 || k > n) return 0;
        var c = 1.0;
        for (var i = 1; i <= k; i++) c = c * (n - k + i) / i;
        return c;
    }

    public static TheoryData<int, int, int, int?> ClassicalCases => new()
    {
        // near, limit depth, limit id → the (depth, id)-smallest accepted row
        { 0, Ray.Unbounded, 6, 1 },  // depths 10, 4, 8, 8: id 1 at 4
        { 5, 15, 6, 2 },             // 10, 8, 8: the tie at 8 goes to id 2
        { 0, 8, 3, 1 },              // strict closer than (8, 3): ids 1 and 2; depth 4 wins
        { 5, 8, 3, 2 },              // ids 2 only (id 3 is the limit itself)
        { 9, 15, 6, 0 },
        { 11, 15, 6, null },
    };

    [Theory]
    [MemberData(nameof(ClassicalCases))]
    public void ClassicalReturnsTheSmallestDepthThenId(int near, int limitDepth, int limitId, int? expected)
    {
        using var search = new ClassicalHitSearch();
        var outcome = Assert.Single(search.Run([new HitQuery(Stack, new HitWindow(near, limitDepth, limitId))]));
        Assert.Equal(expected, outcome.Primitive);
        Assert.True(outcome.Certain);
        Assert.Equal(new SearchCost(0, 0, 6, 0), outcome.Cost); // N = 6 classical tests, no queries
    }

    [Fact]
    public void ClassicalAnswersABatchInOrder()
    {
        using var search = new ClassicalHitSearch();
        var windows = Enumerable.Range(0, 300).Select(k => HitWindow.Range(k % 12, 15, 6)).ToArray();
        var outcomes = search.Run(windows.Select(w => new HitQuery(Stack, w)).ToArray());
        // near 0..4 → id 1 (depth 4); 5..8 → id 2 (8, tie); 9..10 → id 0 (10); 11 → none.
        for (var k = 0; k < windows.Length; k++)
            Assert.Equal(windows[k].Near switch { <= 4 => 1, <= 8 => 2, <= 10 => 0, _ => (int?)null }, outcomes[k].Primitive);
    }

    [Theory]
    [InlineData(1, 1)]
    [InlineData(3, 1)]
    [InlineData(4, 2)]
    [InlineData(8, 2)]
    [InlineData(9, 3)]
    [InlineData(16, 4)]
    [InlineData(20, 4)]
    [InlineData(4096, 64)]
    public void RandomizedTestsFloorSqrtN(int count, int tested)
    {
        Assert.Equal(tested, RandomizedHitSearch.SampleSize(count));
        if (count > 20) return;
        using var search = new RandomizedHitSearch(new SeededRandom(5));
        var outcomes = search.Run(Enumerable.Repeat(new HitQuery(Spread(count, 1), HitWindow.Range(0, 15, count)), 50).ToArray());
        Assert.All(outcomes, o => Assert.Equal(new SearchCost(0, 0, tested, 0), o.Cost));
        // Certain only when every primitive was tested.
        Assert.All(outcomes, o => Assert.Equal(tested == count, o.Certain));
    }

    [Fact]
    public void RandomizedIsReproducibleForASeed()
    {
        var query = new HitQuery(Spread(20, 5), HitWindow.Range(0, 15, 20));
        string Run(ulong seed)
        {
            using var search = new RandomizedHitSearch(new SeededRandom(seed));
            return string.Join(",", search.Run(Enumerable.Repeat(query, 200).ToArray()).Select(o => o.Primitive?.ToString() ?? "-"));
        }
        Assert.Equal(Run(11), Run(11));
        // 200 searches that each miss with probability C(15, 4)/C(20, 4) ≈ 0.28: two seeds agree on all with negligible probability.
        Assert.NotEqual(Run(11), Run(12));
    }

    [Theory]
    [InlineData(16, 1)]  // k = 4: p = 4/16 exactly
    [InlineData(20, 5)]
    [InlineData(10, 2)]  // k = 3
    [InlineData(16, 13)] // only 3 rows fail and k = 4 distinct rows are tested: always found
    [InlineData(16, 0)]
    public void RandomizedHitRateIsTheHypergeometricOne(int count, int accepted)
    {
        const int searches = 20_000;
        var k = (int)Math.Floor(Math.Sqrt(count));
        // P(at least one of k distinct uniformly drawn rows is accepted) = 1 − C(N − t, k) / C(N, k).
        var p = 1 - Choose(count - accepted, k) / Choose(count, k);
        var table = Spread(count, accepted);
        Assert.Equal(accepted, table.Marked(HitWindow.Range(0, 15, count)).MarkedCount);
        using var search = new RandomizedHitSearch(new SeededRandom(17));
        var found = search.Run(Enumerable.Repeat(new HitQuery(table, HitWindow.Range(0, 15, count)), searches).ToArray())
            .Count(o => o.Primitive is not null);
        StatisticalBounds.AssertBinomial(found, p, searches, $"randomized hits, N = {count}, t = {accepted}, k = {k}");
    }

    [Fact]
    public void RandomizedReturnsTheBestTestedRow()
    {
        // Accepted rows in (depth, id) order: 12 (z 5), 3 (z 9), 7 (z 9), 0 (z 11), 16 (z 14); N = 20, k = 4.
        // The j-th of them is returned when it is tested and the j − 1 better ones are not:
        // C(N − j, k − 1) / C(N, k); none is returned with probability C(N − 5, k) / C(N, k).
        var table = Layered(20, new Dictionary<int, int> { [12] = 5, [3] = 9, [7] = 9, [0] = 11, [16] = 14 });
        int[] order = [12, 3, 7, 0, 16];
        var expected = order.Select((_, j) => Choose(19 - j, 3) / Choose(20, 4)).Append(Choose(15, 4) / Choose(20, 4)).ToArray();
        using var search = new RandomizedHitSearch(new SeededRandom(23));
        var outcomes = search.Run(Enumerable.Repeat(new HitQuery(table, table.FullRange), 30_000).ToArray());
        var cells = outcomes.Select(o => o.Primitive is { } p ? Array.IndexOf(order, p) : order.Length).ToArray();
        Assert.DoesNotContain(-1, cells);
        StatisticalBounds.AssertFits(StatisticalBounds.Histogram(cells, order.Length + 1), expected, "randomized: which accepted row is returned");
    }

    private static QuantumHitSearch Quantum(ulong seed) =>
        new(new AnalyticEngine(new SeededRandom(seed).Fork(RandomStreams.Engine)), new SeededRandom(seed).Fork(RandomStreams.Search), new QSearchOptions());

    public static TheoryData<int, int, int, int[]> QuantumWindows => new()
    {
        { 0, Ray.Unbounded, 6, [0, 1, 2, 3] },
        { 0, 8, 3, [1, 2] },
        { 5, 15, 6, [0, 2, 3] },
        { 5, 8, 3, [2] },
        { 11, 15, 6, [] },
    };

    [Theory]
    [MemberData(nameof(QuantumWindows))]
    public void QuantumFindsOnlyAcceptedRowsAtTheExactRate(int near, int limitDepth, int limitId, int[] accepted)
    {
        const int searches = 4000;
        var window = new HitWindow(near, limitDepth, limitId);
        using var search = Quantum(31);
        var outcomes = search.Run(Enumerable.Repeat(new HitQuery(Stack, window), searches).ToArray());
        Assert.Equal("analytic", search.Name);
        Assert.All(outcomes, o => Assert.False(o.Certain));
        // No false positives: whatever is returned, verify-rpc accepts under the query's window.
        Assert.All(outcomes.Where(o => o.Primitive is not null), o => Assert.Contains(o.Primitive!.Value, accepted));
        var found = outcomes.Where(o => o.Primitive is not null).Select(o => o.Primitive!.Value).ToArray();
        if (accepted.Length == 0)
        {
            Assert.Empty(found);
            return;
        }
        var missRate = QSearchExpectations.FalseNegative(6, accepted.Length, new QSearchSchedule(6));
        StatisticalBounds.AssertBinomial(found.Length, 1 - missRate, searches, $"QSearch finds, t = {accepted.Length} of 6");
        // Found rows are uniform over the accepted ones: no row's depth or id biases the marked set.
        if (accepted.Length > 1)
            StatisticalBounds.AssertFits(accepted.Select(a => found.Count(f => f == a)).ToArray(),
                accepted.Select(_ => 1.0 / accepted.Length).ToArray(), "QSearch: which accepted row");
    }

    [Theory]
    [InlineData(6, 0)]
    [InlineData(6, 2)]
    [InlineData(20, 1)]
    [InlineData(20, 5)]
    public void QuantumCountsFollowTheConventions(int count, int accepted)
    {
        var table = count == 6 ? Stack : Spread(count, accepted);
        var window = count == 6 ? (accepted == 0 ? HitWindow.Range(11, 15, 6) : HitWindow.Closer(0, 8, 3, TieBreak.Strict)) : table.FullRange;
        Assert.Equal(accepted, table.Marked(window).MarkedCount);
        var bounds = new QSearchSchedule(count).Bounds;
        using var search = Quantum(41);
        var outcomes = search.Run(Enumerable.Repeat(new HitQuery(table, window), 2000).ToArray());
        foreach (var (primitive, _, cost) in outcomes)
        {
            // One classical verification per Grover run; the first run samples the superposition (r = 0, no
            // query), every later run has r ≥ 1 and costs r + 1 conservative, r paper.
            Assert.Equal(cost.GroverRuns, cost.ClassicalTests);
            Assert.InRange(cost.GroverRuns, 1, bounds.Count + 1);
            Assert.Equal(cost.QueriesPaper + (cost.GroverRuns - 1), cost.QueriesConservative);
            Assert.InRange(cost.QueriesPaper, cost.GroverRuns - 1, bounds.Take((int)cost.GroverRuns - 1).Sum());
            // A miss means the whole schedule ran.
            if (primitive is null) Assert.Equal(bounds.Count + 1, cost.GroverRuns);
        }
        if (accepted == 0) Assert.All(outcomes, o => Assert.Null(o.Primitive));
        else Assert.Contains(outcomes, o => o.Cost.GroverRuns > 1); // the relation above was exercised with r ≥ 1
    }

    [Fact]
    public void QuantumIsReproducibleForASeed()
    {
        var query = new HitQuery(Spread(20, 2), HitWindow.Range(0, 15, 20));
        string Run(ulong seed)
        {
            using var search = Quantum(seed);
            return string.Join(";", search.Run(Enumerable.Repeat(query, 200).ToArray()).Select(o => $"{o.Primitive}:{o.Cost}"));
        }
        Assert.Equal(Run(3), Run(3));
        Assert.NotEqual(Run(3), Run(4));
    }
}
