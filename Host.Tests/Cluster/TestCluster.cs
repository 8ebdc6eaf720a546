using System.Net;
using System.Net.Sockets;
using System.Text.Json.Nodes;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using Microsoft.Extensions.Time.Testing;
using Orleans.Runtime;
using QuantumRayTracing.Cluster;

namespace QuantumRayTracing.Tests.Cluster;

/// <summary>
/// Worker silos in this test process with localhost membership, on free ports, each over the executor a test
/// gives it (real Node bridges, or one that hangs or dies), and the cluster file a render would use. The silos
/// log nothing: the faults here are on purpose.
/// </summary>
public sealed class TestCluster : IDisposable
{
    private readonly List<IHost> _silos = [];
    private readonly ScratchDirectory _scratch = new("qrt-cluster");

    public TestCluster(double chunkTimeoutSeconds, params IChunkExecutor[] executors) : this(chunkTimeoutSeconds, null, executors) { }

    /// <summary>Membership through the Redis server at <paramref name="redis"/> (host:port) when given, else localhost.</summary>
    public TestCluster(double chunkTimeoutSeconds, string? redis, params IChunkExecutor[] executors) : this(chunkTimeoutSeconds, redis, null, executors) { }

    /// <summary>Workers and clients that talk over mutual TLS with the PKCS#12 file <paramref name="certificate"/> when given.</summary>
    public TestCluster(double chunkTimeoutSeconds, string? redis, string? certificate, params IChunkExecutor[] executors)
    {
        var ports = FreePorts(1 + Math.Max(1, executors.Length) * 2);
        // Without workers the file still names a gateway port, one nothing listens on.
        var gateways = Enumerable.Range(0, Math.Max(1, executors.Length)).Select(k => ports[1 + 2 * k + 1]).ToArray();
        ConfigPath = Path.Combine(_scratch.Path, "cluster.json");
        var membership = redis is null
            ? $$""" "clustering": "localhost", "primaryPort": {{ports[1]}}, "gateways": [{{string.Join(", ", gateways)}}] """
            : $$""" "clustering": "redis", "redis": "{{redis}}" """;
        File.WriteAllText(ConfigPath, $$"""
            { "clusterId": "test-{{Guid.NewGuid():N}}", {{membership}}, "chunkTimeoutSeconds": {{chunkTimeoutSeconds}}{{(certificate is null ? "" : $", \"certificate\": {System.Text.Json.JsonSerializer.Serialize(certificate)}")}} }
            """);
        var config = ClusterConfig.Load(ConfigPath);
        for (var k = 0; k < executors.Length; k++)
        {
            var silo = WorkerSilo.Build(config, ports[1 + 2 * k], ports[1 + 2 * k + 1], executors[k], advertise: "127.0.0.1", logFrom: LogLevel.None);
            silo.Start();
            _silos.Add(silo);
        }
    }

    public string ConfigPath { get; }

    public IReadOnlyList<IHost> Silos => _silos;

    /// <summary>Silo <paramref name="k"/>'s address as the cluster's clients name its worker.</summary>
    public string SiloAddress(int k) => _silos[k].Services.GetRequiredService<ILocalSiloDetails>().SiloAddress.ToParsableString();

    /// <summary>Chunks a silo's grain has finished (answered or failed).</summary>
    public long Served(int silo) => _silos[silo].Services.GetRequiredService<WorkerStatistics>().Served;

    public void Dispose()
    {
        foreach (var silo in _silos)
        {
            try
            {
                // The test is over: stop at once, without the graceful stop a hung request would hold for seconds.
                silo.StopAsync(new CancellationToken(canceled: true)).WaitAsync(TimeSpan.FromSeconds(10)).GetAwaiter().GetResult();
            }
            catch (Exception e) when (e is TimeoutException or OperationCanceledException or ObjectDisposedException)
            {
                // A silo a test stopped on purpose, or one still busy with a hung request.
            }
            silo.Dispose();
        }
        _scratch.Dispose();
    }

    /// <summary>
    /// Waits for <paramref name="run"/>, moving the chunk time limit's <paramref name="clock"/> past the limit whenever every
    /// request in flight waits on the faulty worker <paramref name="bad"/>: so only its chunks can time out, however slow or
    /// loaded the machine. Polled in real time; the two-minute deadline only ends a test that is failing anyway.
    /// </summary>
    public static void WaitPastTheFaultyWorker(Task run, ClusterTransport transport, FakeTimeProvider clock, string bad, string good, double chunkSeconds, Func<string> state)
    {
        var deadline = DateTime.UtcNow + TimeSpan.FromMinutes(2);
        while (!run.Wait(20))
        {
            if (transport.InFlightOn(good) == 0 && transport.InFlightOn(bad) > 0)
                clock.Advance(TimeSpan.FromSeconds(chunkSeconds + 1));
            Assert.True(DateTime.UtcNow < deadline, $"{state()} after two minutes");
        }
        run.GetAwaiter().GetResult();
    }

    /// <summary>
    /// Until disposed, a client this test connects takes the first refusal as the answer: the workers here have started
    /// before it connects, so the seconds a client gives workers still starting would only be waited out where a refusal is expected.
    /// </summary>
    public static IDisposable RefusalIsTheAnswer()
    {
        var before = ClusterTransport.ConnectRetriesInThisFlow.Value;
        ClusterTransport.ConnectRetriesInThisFlow.Value = TimeSpan.Zero;
        return new Restore(() => ClusterTransport.ConnectRetriesInThisFlow.Value = before);
    }

    private sealed class Restore(Action restore) : IDisposable
    {
        public void Dispose() => restore();
    }

    public static int[] FreePorts(int count)
    {
        var listeners = Enumerable.Range(0, count).Select(_ => new TcpListener(IPAddress.Loopback, 0)).ToArray();
        foreach (var l in listeners) l.Start();
        var ports = listeners.Select(l => ((IPEndPoint)l.LocalEndpoint).Port).ToArray();
        foreach (var l in listeners) l.Stop();
        return ports;
    }
}

/// <summary>Answers every run request with its own expression, as a one-shot result: which request got which answer is visible.</summary>
public sealed class EchoExecutor : IChunkExecutor
{
    private int _calls;

    public int Calls => Volatile.Read(ref _calls);

    public int Capacity => 2;

    public async Task<JsonNode> Execute(JsonObject request)
    {
        Interlocked.Increment(ref _calls);
        await Task.Delay(20);
        return new JsonArray(request["expr"]!.GetValue<string>());
    }
}

/// <summary>Takes every request and never answers: a worker whose bridges hang.</summary>
public sealed class HangingExecutor : IChunkExecutor
{
    private int _calls;

    public int Calls => Volatile.Read(ref _calls);

    public int Capacity => 2;

    public async Task<JsonNode> Execute(JsonObject request)
    {
        Interlocked.Increment(ref _calls);
        await Task.Delay(Timeout.Infinite);
        throw new InvalidOperationException("unreachable");
    }
}

/// <summary>On its first request stops the silo it runs in, with the request in hand: a worker that dies mid-chunk.</summary>
public sealed class DyingExecutor : IChunkExecutor
{
    private int _calls;

    public IHost? Silo { get; set; }

    public int Calls => Volatile.Read(ref _calls);

    public int Capacity => 2;

    public async Task<JsonNode> Execute(JsonObject request)
    {
        if (Interlocked.Increment(ref _calls) == 1) _ = Task.Run(() => Silo!.StopAsync());
        await Task.Delay(Timeout.Infinite);
        throw new InvalidOperationException("unreachable");
    }
}

/// <summary>
/// On its first request freezes, as a process stopped with SIGSTOP would: the request is never answered and the worker's load,
/// which a heartbeat asks for, no longer comes either until <see cref="Thaw"/> (or a minute, long past any test). Its connection
/// stays open.
/// </summary>
public sealed class FrozenExecutor : IChunkExecutor
{
    private readonly ManualResetEventSlim _thawed = new();
    private int _calls;

    public int Calls => Volatile.Read(ref _calls);

    public int Capacity
    {
        get
        {
            if (Calls > 0) _thawed.Wait(TimeSpan.FromMinutes(1));
            return 2;
        }
    }

    /// <summary>Lets the load answers it holds go, so the silo can stop.</summary>
    public void Thaw() => _thawed.Set();

    public async Task<JsonNode> Execute(JsonObject request)
    {
        Interlocked.Increment(ref _calls);
        await Task.Delay(Timeout.Infinite);
        throw new InvalidOperationException("unreachable");
    }
}
