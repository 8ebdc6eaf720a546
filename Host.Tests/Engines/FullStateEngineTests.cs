using QuantumRayTracing.Engines;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Statistics;

namespace QuantumRayTracing.Tests.Engines;

/// <summary>
/// The full-state simulator's measurements cannot be seeded, so every check here is statistical,
/// each with false-failure probability <see cref="StatisticalBounds.FalseFailure"/>.
/// </summary>
[Collection(QSharpCollection.Name)]
public class FullStateEngineTests(FullStateFixture fixture)
{
    /// <summary>
    /// Each case gets the shots at which its check rejects one iteration fewer or more and one marked row fewer or more
    /// with probability ≥ 0.99, in steps of 50 (<see cref="EngineDistributionChecks.ShotsFor"/>): 4,350 shots in all, where
    /// 1,500 for every case (21,000) gave the N = 12 sample its power 0.990 against t = 3 and the others far more than they need.
    /// By case: 250, 300, 300, 800 (N = 64, r = 6 against r = 5), 50, 150, 50, 150, 50, 50, 50, 200, 350, 1,550 (N = 12, r = 0:
    /// p = 1/6 against 1/4). False-failure probability per case unchanged, <see cref="StatisticalBounds.FalseFailure"/>.
    /// </summary>
    [Fact]
    public void SuccessMatchesClosedForm() =>
        EngineDistributionChecks.SuccessMatchesClosedForm(fixture.Engine, c => EngineDistributionChecks.ShotsFor(c.Count, c.Marked.Length, c.Iterations, step: 50));

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

    [Fact]
    public void ScheduleExpressionListsEveryRun()
    {
        var marked = new MarkedSet(8, [1, 6]);
        var schedules = new[]
        {
            new[] { new GroverRequest(marked, 0), new GroverRequest(marked, 2) },
            new[] { new GroverRequest(new MarkedSet(4, []), 1) },
        };
        Assert.Equal("QuantumRayTracing.Search.MeasureGroverSchedules([(8, [1, 6], [0, 2]), (4, [0, size = 0], [1])])", FullStateEngine.ScheduleExpression(schedules));
    }

    [Fact]
    public void ScheduleStopsAfterTheFirstMarkedIndex()
    {
        // Outcomes certain on every run: N = 4, t = 1 finds the index after one iteration (sin²(3θ) = 1 at
        // sin²θ = 1/4); t = N finds it in the sample; t = 0 never does, so every run comes back.
        var one = new MarkedSet(4, [2]);
        var all = new MarkedSet(8, [0, 1, 2, 3, 4, 5, 6, 7]);
        var none = new MarkedSet(8, []);
        var measured = fixture.Engine.MeasureSchedules(
        [
            [new GroverRequest(one, 1), new GroverRequest(one, 1), new GroverRequest(one, 1)],
            [new GroverRequest(all, 0), new GroverRequest(all, 1)],
            [new GroverRequest(none, 0), new GroverRequest(none, 1), new GroverRequest(none, 2)],
        ]);
        Assert.Equal([2], measured[0]);
        Assert.Single(measured[1]);
        Assert.Equal(3, measured[2].Length);
        Assert.All(measured[2], i => Assert.InRange(i, 0, 7));
    }

    [Theory]
    [InlineData(2, new[] { 1 })]
    [InlineData(3, new[] { 0, 2 })]
    [InlineData(5, new[] { 4 })]
    [InlineData(8, new[] { 0, 3, 7 })]
    [InlineData(16, new[] { 5, 6, 9, 15 })]
    [InlineData(64, new[] { 0, 17, 40, 63 })]
    [InlineData(64, new int[0])]
    public void PhaseConstructionMatchesTheLibrarysControlledZOnEveryBasisState(int count, int[] marked)
    {
        // Deterministic: equal phases leave the kickback control in |+⟩ with certainty (see the Q# remarks).
        var list = marked.Length == 0 ? "[0, size = 0]" : $"[{string.Join(", ", marked)}]";
        var value = fixture.Engine.Pool.Bridges[0].Run($"QuantumRayTracing.Search.CompareMarkingOracleConstructions({count}, {list})")[0];
        var states = value.Trim('[', ']').Split("), (");
        Assert.Equal(1 << SearchRegisters.For(count).IndexQubits, states.Length);
        Assert.All(states, s => Assert.Equal("true, true, true", s.Trim('(', ')')));
    }
}
