using QuantumRayTracing.Cluster;

namespace QuantumRayTracing.Tests.Cluster;

/// <summary>
/// Membership through Redis, end to end: a Redis-compatible server in this process, two workers that find each
/// other through it, and requests from a render's side that reach both.
/// </summary>
public sealed class RedisMembershipTests : IDisposable
{
    private readonly InProcessRedis _redis = new();

    [Fact]
    public void TwoWorkersJoinThroughRedisAndBothServe()
    {
        var (first, second) = (new EchoExecutor(), new EchoExecutor());
        using var cluster = new TestCluster(120, _redis.Address, first, second);
        using var pool = ClusterBridges.Start(cluster.ConfigPath, 1);

        Assert.Equal(first.Capacity + second.Capacity, pool.Workers);
        Assert.Contains("redis membership", pool.Where);
        var answers = new string[40];
        pool.ForEach(Enumerable.Range(0, answers.Length).ToArray(), (k, bridge) => answers[k] = Assert.Single(bridge.Run($"Request({k})")));
        Assert.Equal(Enumerable.Range(0, answers.Length).Select(k => $"Request({k})"), answers);
        Assert.True(first.Calls > 0 && second.Calls > 0, $"requests served: {first.Calls} and {second.Calls}; both workers should take some");
    }

    public void Dispose() => _redis.Dispose();
}
