using QuantumRayTracing.Cluster;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Tests.Engines;
using QuantumRayTracing.Tests.Statistics;

namespace QuantumRayTracing.Tests.Cluster;

/// <summary>
/// The fullstate engine, unchanged, on a two-worker cluster with real bridges: the same distributions as the
/// closed form and the analytic engine (false-failure probability <see cref="StatisticalBounds.FalseFailure"/>
/// per check), with chunks served by both workers.
/// </summary>
public sealed class ClusterEngineTests
{
    [Fact]
    public void FullStateOnTwoWorkersMatchesClosedFormAndAnalytic()
    {
        using var first = new WorkerBridges(1);
        using var second = new WorkerBridges(1);
        using var cluster = new TestCluster(120, first, second);
        using var engine = new FullStateEngine(ClusterBridges.Start(cluster.ConfigPath, 1), maxRequestsPerCall: 200);

        EngineDistributionChecks.SuccessMatchesClosedForm(engine, shots: 400);
        var c = new GroverCase(12, [2, 9], 1, "N = 12, t = 2, r = 1");
        var quantum = EngineDistributionChecks.Sample(engine, c, 3000);
        var analytic = EngineDistributionChecks.Sample(new AnalyticEngine(new SeededRandom(3)), c, 3000);
        StatisticalBounds.AssertSameDistribution(quantum, analytic, "cluster fullstate vs analytic");

        Assert.True(cluster.Served(0) > 0 && cluster.Served(1) > 0, $"chunks served: {cluster.Served(0)} and {cluster.Served(1)}; both workers should take some");
    }
}
