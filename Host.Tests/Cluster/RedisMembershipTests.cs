using System.Diagnostics;
using System.Net.Sockets;
using QuantumRayTracing.Cluster;

namespace QuantumRayTracing.Tests.Cluster;

/// <summary>
/// Membership through Redis, end to end: a Debian <c>redis-server</c> started here on a free port, two workers
/// that find each other through it, and requests from a render's side that reach both.
/// </summary>
public sealed class RedisMembershipTests : IDisposable
{
    private readonly Process _redis;
    private readonly int _port = TestCluster.FreePorts(1)[0];

    public RedisMembershipTests()
    {
        var start = new ProcessStartInfo("redis-server") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        foreach (var argument in new[] { "--port", _port.ToString(), "--bind", "127.0.0.1", "--save", "", "--appendonly", "no" })
            start.ArgumentList.Add(argument);
        try
        {
            _redis = Process.Start(start)!;
        }
        catch (System.ComponentModel.Win32Exception e)
        {
            throw new InvalidOperationException("redis-server not found: install it (README.md, Prerequisites; Debian: apt-get install redis-server)", e);
        }
        _redis.BeginOutputReadLine();
        _redis.BeginErrorReadLine();
        // Ready when it accepts connections.
        var clock = Stopwatch.StartNew();
        while (true)
        {
            try
            {
                using var probe = new TcpClient("127.0.0.1", _port);
                break;
            }
            catch (SocketException) when (clock.Elapsed < TimeSpan.FromSeconds(10))
            {
                Thread.Sleep(100);
            }
        }
    }

    [Fact]
    public void TwoWorkersJoinThroughRedisAndBothServe()
    {
        var (first, second) = (new EchoExecutor(), new EchoExecutor());
        using var cluster = new TestCluster(10, $"127.0.0.1:{_port}", first, second);
        using var pool = ClusterBridges.Start(cluster.ConfigPath, 1);

        Assert.Equal(first.Capacity + second.Capacity, pool.Workers);
        Assert.Contains("redis membership", pool.Where);
        var answers = new string[40];
        pool.ForEach(Enumerable.Range(0, answers.Length).ToArray(), (k, bridge) => answers[k] = Assert.Single(bridge.Run($"Request({k})")));
        Assert.Equal(Enumerable.Range(0, answers.Length).Select(k => $"Request({k})"), answers);
        Assert.True(first.Calls > 0 && second.Calls > 0, $"requests served: {first.Calls} and {second.Calls}; both workers should take some");
    }

    public void Dispose()
    {
        _redis.Kill();
        _redis.WaitForExit(5000);
        _redis.Dispose();
    }
}
