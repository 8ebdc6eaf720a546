using QuantumRayTracing.Engines;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Tests.Statistics;

namespace QuantumRayTracing.Tests.Engines;

/// <summary>
/// The full-state simulator's measurements cannot be seeded, so every check here is statistical,
/// each with false-failure probability <see cref="StatisticalBounds.FalseFailure"/>.
/// </summary>
[Collection(QSharpCollection.Name)]
public class FullStateEngineTests(FullStateFixture fixture)
{
    [Fact]
    public void SuccessMatchesClosedForm() =>
        EngineDistributionChecks.SuccessMatchesClosedForm(fixture.Engine, shots: 1500);

    [Fact]
    public void AgreesWithAnalyticEngineInDistribution()
    {
        // Not a power of two, so this also checks the exact uniform preparation over N.
        var c = new GroverCase(12, [2, 9], 1, "N = 12, t = 2, r = 1");
        var quantum = EngineDistributionChecks.Sample(fixture.Engine, c, 6000);
        var analytic = EngineDistributionChecks.Sample(new AnalyticEngine(new SeededRandom(3)), c, 6000);
        StatisticalBounds.AssertSameDistribution(quantum, analytic, "fullstate vs analytic");
        StatisticalBounds.AssertFits(quantum, EngineDistributionChecks.ExactDistribution(c), "fullstate vs exact");
    }

    [Fact]
    public void BatchExpressionListsEveryRequest()
    {
        var requests = new[] { new GroverCase(8, [1, 6], 2, "").Request, new GroverCase(4, [], 0, "").Request };
        Assert.Equal("QuantumRayTracing.Search.MeasureGroverBatch([(8, [1, 6], 2), (4, [0, size = 0], 0)])", FullStateEngine.BatchExpression(requests));
    }

    [Fact]
    public void EmptyBatchNeedsNoCall() => Assert.Empty(fixture.Engine.Measure([]));
}
