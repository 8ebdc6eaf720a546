using QuantumRayTracing.Engines;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Engines;
using QuantumRayTracing.Tests.Statistics;

namespace QuantumRayTracing.Tests.Search;

/// <summary>QSearch and its lock-step driver, checked on the analytic engine; <see cref="QSearchFullStateTests"/> repeats the engine-dependent checks on Q#.</summary>
public class QSearchTests
{
    internal static QSearch[] Searches(MarkedSet marked, int n, ulong seed, MSetRule rule = MSetRule.Ceiling)
    {
        var schedule = new QSearchSchedule(marked.Count, 1.8, rule);
        var root = new SeededRandom(seed);
        return Enumerable.Range(0, n).Select(k => new QSearch(marked, schedule, root.Fork(RandomStreams.FirstSearch + (ulong)k))).ToArray();
    }

    /// <summary>Runs searches and checks: found implies marked, none found when t = 0, not-found rate matches the exact false-negative probability.</summary>
    internal static void CheckFindsAndMisses(IGroverEngine engine, MarkedSet marked, int n, MSetRule rule)
    {
        var searches = Searches(marked, n, seed: 21, rule);
        QSearchDriver.Run(searches, engine);
        Assert.All(searches, s => Assert.True(s.IsDone));
        Assert.All(searches.Where(s => s.Found is not null), s => Assert.True(marked.Contains(s.Found!.Value)));
        var misses = searches.Count(s => s.Found is null);
        if (marked.MarkedCount == 0)
        {
            Assert.Equal(n, misses);
            return;
        }
        var schedule = new QSearchSchedule(marked.Count, 1.8, rule);
        StatisticalBounds.AssertBinomial(misses, QSearchExpectations.FalseNegative(marked.Count, marked.MarkedCount, schedule), n,
            $"{engine.Name}: QSearch misses, N = {marked.Count}, t = {marked.MarkedCount}, {rule}");
    }

    [Theory]
    [InlineData(16, new[] { 9 }, MSetRule.Ceiling)]
    [InlineData(64, new[] { 40 }, MSetRule.Ceiling)]
    [InlineData(64, new[] { 40 }, MSetRule.Round)]
    [InlineData(512, new[] { 3, 300 }, MSetRule.Round)]
    [InlineData(32, new int[0], MSetRule.Ceiling)]
    [InlineData(8, new[] { 0, 1, 2, 3, 4, 5, 6, 7 }, MSetRule.Ceiling)]
    [InlineData(1, new[] { 0 }, MSetRule.Round)]
    public void FindsMarkedIndexOrReportsNotFound(int count, int[] marked, MSetRule rule) =>
        CheckFindsAndMisses(new AnalyticEngine(new SeededRandom(8)), new MarkedSet(count, marked), 20_000, rule);

    [Fact]
    public void CountsFollowTheConventions()
    {
        // t = 0: the sample and every bounded run miss, so every run's r shows in the counts.
        var marked = new MarkedSet(64, []);
        var search = Searches(marked, 1, seed: 4)[0];
        var runs = new List<int>();
        var engine = new AnalyticEngine(new SeededRandom(1));
        while (!search.IsDone)
        {
            var request = search.NextRequest();
            runs.Add(request.Iterations);
            search.Observe(engine.Measure([request])[0]);
        }
        var bounds = new QSearchSchedule(64).Bounds;
        Assert.Equal(bounds.Count + 1, runs.Count);
        Assert.Equal(0, runs[0]);
        for (var l = 1; l < runs.Count; l++) Assert.InRange(runs[l], 1, bounds[l - 1]);
        Assert.Equal(runs.Sum(), search.Cost.QueriesPaper);
        Assert.Equal(runs.Sum() + runs.Count - 1, search.Cost.QueriesConservative);
        Assert.Equal(runs.Count, search.Cost.ClassicalTests);
        Assert.Null(search.Found);
    }

    [Fact]
    public void SameSeedGivesSameSequenceOnAnalyticEngine()
    {
        static string Run(ulong seed)
        {
            var searches = Searches(new MarkedSet(128, [5, 77]), 300, seed);
            QSearchDriver.Run(searches, new AnalyticEngine(new SeededRandom(seed).Fork(RandomStreams.Engine)));
            return string.Join(";", searches.Select(s => $"{s.Found}:{s.LastMeasured}:{s.Cost}"));
        }
        Assert.Equal(Run(9), Run(9));
        Assert.NotEqual(Run(9), Run(10));
    }

    [Fact]
    public void DriverSendsOneBatchPerRound()
    {
        var engine = new CountingEngine(new AnalyticEngine(new SeededRandom(2)));
        var searches = Searches(new MarkedSet(64, []), 50, seed: 3);
        var rounds = QSearchDriver.Run(searches, engine);
        Assert.Equal(new QSearchSchedule(64).Bounds.Count + 1, rounds);
        Assert.Equal(rounds, engine.Calls);
        Assert.Equal(50 * rounds, engine.Requests);
    }

    private sealed class CountingEngine(IGroverEngine inner) : IGroverEngine
    {
        public int Calls, Requests;
        public string Name => inner.Name;

        public IReadOnlyList<int> Measure(IReadOnlyList<GroverRequest> requests)
        {
            Calls++;
            Requests += requests.Count;
            return inner.Measure(requests);
        }

        public void Dispose() { }
    }
}

[Collection(QSharpCollection.Name)]
public class QSearchFullStateTests(FullStateFixture fixture)
{
    [Theory]
    [InlineData(16, new[] { 9 })]
    [InlineData(12, new[] { 4, 10 })]
    [InlineData(16, new int[0])]
    public void FindsMarkedIndexOrReportsNotFound(int count, int[] marked) =>
        QSearchTests.CheckFindsAndMisses(fixture.Engine, new MarkedSet(count, marked), 600, MSetRule.Ceiling);
}
