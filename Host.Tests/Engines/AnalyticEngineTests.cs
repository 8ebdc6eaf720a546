using QuantumRayTracing.Engines;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Tests.Statistics;

namespace QuantumRayTracing.Tests.Engines;

public class AnalyticEngineTests
{
    [Fact]
    public void SuccessMatchesClosedForm() =>
        EngineDistributionChecks.SuccessMatchesClosedForm(new AnalyticEngine(new SeededRandom(11)), shots: 20_000);

    [Fact]
    public void OutcomesFollowTheExactDistribution()
    {
        var c = new GroverCase(12, [2, 9], 1, "N = 12");
        var engine = new AnalyticEngine(new SeededRandom(5));
        StatisticalBounds.AssertFits(EngineDistributionChecks.Sample(engine, c, 60_000), EngineDistributionChecks.ExactDistribution(c), "analytic N = 12");
    }

    [Fact]
    public void SameSeedGivesSameOutcomes()
    {
        var requests = GroverCase.Hard.Select(c => c.Request).ToArray();
        var first = new AnalyticEngine(new SeededRandom(77)).Measure(requests);
        var second = new AnalyticEngine(new SeededRandom(77)).Measure(requests);
        Assert.Equal(first, second);
    }

    [Fact]
    public void DifferentSeedGivesDifferentOutcomes()
    {
        var request = new GroverCase(64, [17], 1, "mostly misses").Request;
        var requests = Enumerable.Repeat(request, 50).ToArray();
        Assert.NotEqual(new AnalyticEngine(new SeededRandom(1)).Measure(requests), new AnalyticEngine(new SeededRandom(2)).Measure(requests));
    }
}
