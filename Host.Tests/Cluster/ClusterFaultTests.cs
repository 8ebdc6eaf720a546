using Microsoft.Extensions.Time.Testing;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Cluster;
using QuantumRayTracing.Tests.Cli;

namespace QuantumRayTracing.Tests.Cluster;

/// <summary>
/// Workers that hang or die with a chunk in hand: the chunk goes to another worker within the chunk time limit,
/// and every request gets exactly one answer, its own. The executors answer with the request's own expression,
/// so a lost, doubled or swapped answer shows.
/// </summary>
public sealed class ClusterFaultTests
{
    private const int Requests = 40;

    private const double ChunkSeconds = 5;

    // Every request through the cluster's bridges; the answers, in request order. The chunk time limit runs on a
    // clock that moves only while every request in flight waits on the faulty worker, and then past the limit:
    // so only the faulty worker's chunks can time out, however slow or loaded the machine. Silo 0 is the faulty one.
    private static string[] RunAll(TestCluster cluster)
    {
        var clock = new FakeTimeProvider();
        using var transport = ClusterTransport.Connect(ClusterConfig.Load(cluster.ConfigPath), clock);
        using var pool = new BridgePool(transport, transport.Capacity);
        Assert.Equal(4, pool.Workers); // both workers joined, two bridges each
        var (bad, good) = (cluster.SiloAddress(0), cluster.SiloAddress(1));
        var answers = new string?[Requests];
        var counts = new int[Requests];
        var run = Task.Run(() => pool.ForEach(Enumerable.Range(0, Requests).ToArray(), (k, bridge) =>
        {
            var shots = bridge.Run($"Request({k})");
            Interlocked.Increment(ref counts[k]);
            answers[k] = Assert.Single(shots);
        }));
        TestCluster.WaitPastTheFaultyWorker(run, transport, clock, bad, good, ChunkSeconds, () => $"{counts.Sum()} of {Requests} requests answered");
        Assert.All(counts, c => Assert.Equal(1, c));
        Assert.True(transport.Retries >= 1, "no chunk was sent again, so the test proved nothing");
        Assert.Contains("sent again after a worker failed to answer", pool.Where);
        return answers!;
    }

    [Fact]
    public void HangingWorkerLosesNothing()
    {
        var (hanging, good) = (new HangingExecutor(), new EchoExecutor());
        using var cluster = new TestCluster(ChunkSeconds, hanging, good);

        var answers = RunAll(cluster);

        Assert.Equal(Enumerable.Range(0, Requests).Select(k => $"Request({k})"), answers);
        Assert.True(hanging.Calls >= 1, "the hanging worker was never given a chunk, so the test proved nothing");
        Assert.Equal(Requests, good.Calls); // each request answered once, by the good worker
    }

    [Fact]
    public void DyingWorkerLosesNothing()
    {
        var (dying, good) = (new DyingExecutor(), new EchoExecutor());
        using var cluster = new TestCluster(ChunkSeconds, dying, good);
        dying.Silo = cluster.Silos[0];

        var answers = RunAll(cluster);

        Assert.Equal(Enumerable.Range(0, Requests).Select(k => $"Request({k})"), answers);
        Assert.True(dying.Calls >= 1, "the dying worker was never given a chunk, so the test proved nothing");
        Assert.Equal(Requests, good.Calls);
    }

    /// <summary>
    /// A worker that freezes with a chunk in hand, its connection open, is noticed by its missed heartbeats, not the chunk time
    /// limit: with a limit of ten minutes on the real clock, every request is answered within two, once each.
    /// </summary>
    [Fact]
    public async Task AFrozenWorkerIsNoticedByItsHeartbeats()
    {
        var (frozen, good) = (new FrozenExecutor(), new EchoExecutor());
        using var cluster = new TestCluster(600, frozen, good);
        using var transport = ClusterTransport.Connect(ClusterConfig.Load(cluster.ConfigPath), heartbeat: TimeSpan.FromMilliseconds(200));
        using var pool = new BridgePool(transport, transport.Capacity);
        var answers = new string?[Requests];
        var run = Task.Run(() => pool.ForEach(Enumerable.Range(0, Requests).ToArray(), (k, bridge) => answers[k] = Assert.Single(bridge.Run($"Request({k})"))));

        try
        {
            await run.WaitAsync(TimeSpan.FromMinutes(2));
        }
        finally
        {
            frozen.Thaw();
        }

        Assert.Equal(Enumerable.Range(0, Requests).Select(k => $"Request({k})"), answers);
        Assert.True(frozen.Calls >= 1, "the frozen worker was never given a chunk, so the test proved nothing");
        Assert.Equal(Requests, good.Calls);
        Assert.True(transport.Retries >= 1, "no chunk was sent again, so the test proved nothing");
    }

    [Fact]
    public void EveryWorkerHangingIsAClusterError()
    {
        using var cluster = new TestCluster(0.5, new HangingExecutor());
        using var pool = ClusterBridges.Start(cluster.ConfigPath, 1);
        var error = Assert.Throws<ClusterException>(() => pool.ForEach([1], (_, bridge) => bridge.Run("Request(1)")));
        Assert.Contains("no answer within the chunk time limit of 0.5 s", error.Message);
    }

    [Fact]
    public void NoReachableWorkerIsExitCodeThreeWithOneLine()
    {
        using var cluster = new TestCluster(5); // the file only: no worker started
        using var _ = TestCluster.RefusalIsTheAnswer();
        var (code, error) = ConsoleCapture.Run("search", "-n", "8", "-s", "2", "--cluster", cluster.ConfigPath);
        Assert.Equal(ExitCodes.QuantumFailure, code);
        var first = error.Split('\n')[0];
        Assert.StartsWith($"error: {cluster.ConfigPath}: no worker of cluster", first);
        Assert.Contains("qrt worker --cluster", first);
    }

    [Fact]
    public void BadClusterFileIsBadInput()
    {
        using var cluster = new TestCluster(5);
        File.WriteAllText(cluster.ConfigPath, """{ "clustering": "mesh" }""");
        var (code, error) = ConsoleCapture.Run("search", "-n", "8", "-s", "2", "--cluster", cluster.ConfigPath);
        Assert.Equal(ExitCodes.BadInput, code);
        Assert.Equal($"error: {cluster.ConfigPath}: field 'clustering' is 'mesh'; choose localhost or redis", error.Trim());
    }
}
