using QuantumRayTracing.Engines;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Statistics;

namespace QuantumRayTracing.Tests.Search;

public sealed class FalseNegativeRateTests
{
    [Theory]
    // Eq. 10 as printed, cos²((M+1)θ) with the table 6 sets, gives 0.150 and 0.075 at N = 8, 16: not table 6's 0.205 and 0.113.
    [InlineData(8, 0.150)]
    [InlineData(16, 0.075)]
    public void Eq10AsPrintedDoesNotGiveTable6(int n, double expected) =>
        Assert.Equal(expected, FalseNegativeRate.Eq10AsPrinted(new QSearchSchedule(n, 1.8, MSetRule.Round), FalseNegativeRate.Uniform(n, n)), 3);

    [Theory]
    // The paper's table 6 (c = 1.8); evaluating at r = M_l reproduces it within 0.015. N = 32 is
    // left out: the table prints M = {1, 2, 3, 6} there, which its own bound M_l < ceil(sqrt N) excludes.
    [InlineData(8, 0.205)]
    [InlineData(16, 0.113)]
    [InlineData(64, 0.057)]
    [InlineData(128, 0.029)]
    [InlineData(256, 0.029)]
    [InlineData(512, 0.015)]
    public void Eq10AtTheBoundReproducesTable6(int n, double table6) =>
        Assert.InRange(FalseNegativeRate.Eq10AtBound(new QSearchSchedule(n, 1.8, MSetRule.Round), FalseNegativeRate.Uniform(n, n)), table6 - 0.015, table6 + 0.015);

    [Fact]
    public void ExactRateAtN64IsBelowTable6() =>
        // QSearch's exact false-negative rate with t uniform on 1..N is about 0.024 at N = 64, below table 6's 0.057.
        Assert.Equal(0.024, FalseNegativeRate.QSearchExact(new QSearchSchedule(64), FalseNegativeRate.Uniform(64, 64)), 3);

    [Theory]
    [InlineData(64, 1, MSetRule.Ceiling)]
    [InlineData(64, 3, MSetRule.Round)]
    [InlineData(12, 2, MSetRule.Ceiling)]
    public void ExactRateMatchesSimulatedSearches(int n, int t, MSetRule rule)
    {
        // 20,000 QSearch runs on the analytic engine against a fixed marked set of size t.
        const int searches = 20_000;
        var schedule = new QSearchSchedule(n, rule: rule);
        var marked = new MarkedSet(n, Enumerable.Range(0, t));
        var random = new SeededRandom(17);
        using var engine = new AnalyticEngine(random.Fork(RandomStreams.Engine));
        // Every search draws its iteration counts from one shared stream, in the driver's fixed order.
        var shared = random.Fork(RandomStreams.Search);
        var runs = Enumerable.Range(0, searches).Select(_ => new QSearch(marked, schedule, shared)).ToArray();
        QSearchDriver.Run(runs, engine);
        StatisticalBounds.AssertBinomial(runs.Count(s => s.Found is null), FalseNegativeRate.QSearchExact(schedule, t), searches, $"misses at N = {n}, t = {t}");
    }

    [Fact]
    public void FixedScheduleMissIsTheProductOverItsRuns()
    {
        // r = 2, 2, 5 at N = 64, t = 1: sin θ = 1/8; each run misses with cos²((2r + 1)θ).
        var theta = Math.Asin(1.0 / 8);
        var expected = Math.Pow(Math.Cos(5 * theta), 4) * Math.Pow(Math.Cos(11 * theta), 2);
        Assert.Equal(expected, FalseNegativeRate.QSearchExact(QSearchSchedule.Fixed(64, [2, 2, 5]), 1), 12);
    }

    [Fact]
    public void RandomizedRateIsEq11()
    {
        // N = 16, k = 4 draws, t = 3: (13/16)(12/15)(11/14)(10/13).
        var pt = new double[17];
        pt[3] = 1;
        Assert.Equal(13.0 / 16 * 12 / 15 * 11 / 14 * 10 / 13, FalseNegativeRate.Randomized(16, 4, pt), 12);
        // Past N − k primitives every draw hits one.
        pt[3] = 0;
        pt[13] = 1;
        Assert.Equal(0, FalseNegativeRate.Randomized(16, 4, pt));
    }
}
