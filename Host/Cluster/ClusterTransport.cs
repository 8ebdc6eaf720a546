using System.Text.Json.Nodes;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Hosting;
using Microsoft.Extensions.Logging;
using Orleans.Configuration;
using Orleans.Runtime;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Output;
using StackExchange.Redis;

namespace QuantumRayTracing.Cluster;

/// <summary>
/// Sends bridge requests to a cluster's workers: each request goes to the least loaded worker; a worker that
/// fails to answer (it died, hangs past the chunk time limit, misses its heartbeats, cannot be reached) is dropped and
/// the request goes to another, so every request gets exactly one answer or the render stops with a <see cref="ClusterException"/>.
/// What a worker's bridge reports (a Q# failure, a rejected request) is raised as the local bridge raises it.
/// </summary>
public sealed class ClusterTransport : IBridgeTransport, IDisposable
{
    /// <summary>How long connecting to the cluster and asking the workers' sizes may take.</summary>
    public static readonly TimeSpan ConnectTimeout = TimeSpan.FromSeconds(30);

    /// <summary>How long connecting keeps trying while the gateways refuse (workers still starting).</summary>
    public static readonly TimeSpan ConnectRetries = TimeSpan.FromSeconds(5);

    /// <summary>
    /// Replaces <see cref="ConnectRetries"/> for the connections made in the current async flow: a test whose workers have
    /// all started, or that expects a refusal, needs no time for workers still starting.
    /// </summary>
    internal static readonly AsyncLocal<TimeSpan?> ConnectRetriesInThisFlow = new();

    private readonly IHost _host;
    private readonly ClusterConfig _config;
    private readonly Worker[] _workers;
    private readonly TimeProvider _clock;
    private readonly Lock _gate = new();
    private int _retries;

    private readonly TimeSpan _heartbeat;

    private ClusterTransport(IHost host, ClusterConfig config, Worker[] workers, TimeProvider clock, TimeSpan heartbeat) =>
        (_host, _config, _workers, _clock, _heartbeat) = (host, config, workers, clock, heartbeat);

    /// <summary>Bridges over all workers.</summary>
    public int Capacity => _workers.Sum(w => w.Capacity);

    /// <summary>Requests sent again to another worker after one failed to answer.</summary>
    public int Retries => Volatile.Read(ref _retries);

    /// <summary>Requests waiting for an answer from the worker whose silo address is <paramref name="silo"/> (Orleans' parsable form).</summary>
    public int InFlightOn(string silo)
    {
        lock (_gate) return _workers.Where(w => w.Silo == silo).Sum(w => w.Busy);
    }

    /// <summary>Where requests run, for reports: the cluster, its workers and bridges, and the chunks sent again so far.</summary>
    public RunPlace Place
    {
        get
        {
            var (membership, retries) = (_config.Clustering.ToString().ToLowerInvariant(), Retries);
            var description = $"cluster '{_config.ClusterId}' ({membership} membership, {_config.Path}): {_workers.Length} worker{(_workers.Length == 1 ? "" : "s")}, {Capacity} bridges{(retries > 0 ? $"; {retries} chunk{(retries == 1 ? "" : "s")} sent again after a worker failed to answer" : "")}";
            return new RunPlace(description, RunPlace.ClusterKind, Capacity, _config.ClusterId, membership, _workers.Length, retries);
        }
    }

    /// <summary>
    /// Connects to the cluster and asks each worker how many bridges it has; none reachable is a <see cref="ClusterException"/>.
    /// <paramref name="chunkClock"/> measures the chunk time limit (default: the system's); <paramref name="heartbeat"/> is
    /// <see cref="DefaultHeartbeat"/> unless given.
    /// </summary>
    public static ClusterTransport Connect(ClusterConfig config, TimeProvider? chunkClock = null, TimeSpan? heartbeat = null)
    {
        Exception? refused = null;
        var retries = ConnectRetriesInThisFlow.Value ?? ConnectRetries;
        var clock = System.Diagnostics.Stopwatch.StartNew();
        var builder = Host.CreateApplicationBuilder(new HostApplicationBuilderSettings { Args = [], ContentRootPath = AppContext.BaseDirectory });
        builder.Logging.ClearProviders();
        builder.UseOrleansClient(client =>
        {
            client.Configure<ClusterOptions>(o => (o.ClusterId, o.ServiceId) = (config.ClusterId, WorkerSilo.ServiceId));
            // Workers still starting get a few seconds; then the first refusal is the answer.
            client.UseConnectionRetryFilter(async (e, cancel) =>
            {
                refused = e;
                if (clock.Elapsed > retries) return false;
                await Task.Delay(500, cancel);
                return true;
            });
            // The chunk time limit is ours (Send); Orleans' own limit only backs it up.
            client.Configure<ClientMessagingOptions>(o => o.ResponseTimeout = config.ChunkTimeout + TimeSpan.FromMinutes(1));
            if (config.Certificate is { } file)
            {
                var certificate = ClusterCertificate.Load(config.Path, file);
                client.UseTls(certificate, o => ClusterCertificate.Configure(o, certificate));
            }
            if (config.Clustering == ClusteringKind.Localhost)
                client.UseLocalhostClustering(config.Gateways.ToArray(), WorkerSilo.ServiceId, config.ClusterId);
            else
                client.UseRedisClustering(o => o.ConfigurationOptions = ConfigurationOptions.Parse(config.Redis!));
        });
        var host = builder.Build();
        var where = config.Clustering == ClusteringKind.Localhost
            ? $"gateway ports {string.Join(", ", config.Gateways)}"
            : $"Redis {config.Redis}";
        try
        {
            host.StartAsync().WaitAsync(ConnectTimeout).GetAwaiter().GetResult();
            var client = host.Services.GetRequiredService<IClusterClient>();
            var silos = client.GetGrain<IManagementGrain>(0).GetHosts(onlyActive: true).WaitAsync(ConnectTimeout).GetAwaiter().GetResult();
            var workers = silos.Keys
                .Select(silo => silo.ToParsableString())
                .Select(silo => (silo, grain: client.GetGrain<IChunkWorker>(silo)))
                .Select(w => (w.silo, w.grain, load: w.grain.Load().WaitAsync(ConnectTimeout)))
                .ToArray();
            var reachable = new List<Worker>();
            foreach (var (silo, grain, load) in workers)
            {
                try
                {
                    reachable.Add(new Worker(silo, grain, load.GetAwaiter().GetResult().Bridges));
                }
                catch (Exception e) when (e is not OutOfMemoryException)
                {
                    // A member that does not answer is left out; the others serve the render.
                }
            }
            if (reachable.Count == 0) throw new ClusterException($"{config.Path}: the cluster '{config.ClusterId}' at {where} has no worker that answers");
            return new ClusterTransport(host, config, [.. reachable], chunkClock ?? TimeProvider.System, heartbeat ?? DefaultHeartbeat);
        }
        catch (Exception e) when (e is not ClusterException and not OutOfMemoryException)
        {
            host.Dispose();
            var why = e is TimeoutException && refused is not null ? refused : e;
            throw new ClusterException($"{config.Path}: no worker of cluster '{config.ClusterId}' reachable at {where} ({FirstLine(why.Message)}); start one with 'qrt worker --cluster {config.Path}'{(config.Certificate is null ? "; workers that hold a certificate serve only clients whose cluster file names it" : "")}", e);
        }
        catch
        {
            host.Dispose();
            throw;
        }
    }

    /// <summary>How often a render asks a worker holding one of its chunks whether it still answers; it may take twice as long to answer.</summary>
    public static readonly TimeSpan DefaultHeartbeat = TimeSpan.FromSeconds(5);

    /// <summary>Heartbeats missed in a row after which a worker holding a chunk counts as lost (one missed may be a busy moment).</summary>
    public const int MissedHeartbeats = 3;

    /// <summary>How often one request may go to the same worker when its calls fail while the worker still answers.</summary>
    public const int AttemptsPerWorker = 3;

    public JsonNode Send(JsonObject request)
    {
        var text = request.ToJsonString();
        var attempts = new Dictionary<Worker, int>();
        Exception? last = null;
        while (Pick(attempts) is { } worker)
        {
            ChunkReply reply;
            try
            {
                reply = Await(worker, worker.Grain.Run(text));
            }
            catch (Exception e) when (e is not OutOfMemoryException)
            {
                // Died, hung or unreachable: its answer, if one ever comes, is dropped with the task. A call can also fail on
                // the way while its worker lives (through another worker's gateway that died, say): a worker that answers stays.
                last = e;
                if (e is TimeoutException or WorkerLostException || !Answers(worker)) worker.Failed = true;
                Interlocked.Increment(ref _retries);
                continue;
            }
            finally
            {
                lock (_gate) worker.Busy--;
            }
            return Unpack(reply);
        }
        var why = last switch
        {
            TimeoutException => $"no answer within the chunk time limit of {_config.ChunkTimeout.TotalSeconds:0.###} s",
            WorkerLostException lost => lost.Message,
            _ => FirstLine(last?.Message ?? "no worker left"),
        };
        throw new ClusterException($"{_config.Path}: no worker of cluster '{_config.ClusterId}' could run a chunk ({why}); {_workers.Count(w => w.Failed)} of {_workers.Length} workers failed", last);
    }

    // The chunk's answer within the chunk time limit; while it runs, the worker is asked for its load every heartbeat, so a
    // worker killed with the chunk in hand is noticed in seconds even when its connection does not say so.
    private ChunkReply Await(Worker worker, Task<ChunkReply> call)
    {
        var answer = call.WaitAsync(_config.ChunkTimeout, _clock);
        var missed = 0;
        while (Task.WaitAny([answer], _heartbeat) < 0)
        {
            missed = Answers(worker) ? 0 : missed + 1;
            if (missed >= MissedHeartbeats) throw new WorkerLostException($"a worker stopped answering for {MissedHeartbeats} heartbeats with a chunk in hand");
        }
        return answer.GetAwaiter().GetResult();
    }

    private bool Answers(Worker worker)
    {
        try
        {
            worker.Grain.Load().WaitAsync(2 * _heartbeat).GetAwaiter().GetResult();
            return true;
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            return false;
        }
    }

    /// <summary>
    /// The least busy worker, relative to its bridges, that has not failed, among those this request has tried least often
    /// (at most <see cref="AttemptsPerWorker"/> times each).
    /// </summary>
    private Worker? Pick(Dictionary<Worker, int> attempts)
    {
        lock (_gate)
        {
            var worker = _workers.Where(w => !w.Failed && attempts.GetValueOrDefault(w) < AttemptsPerWorker)
                .MinBy(w => (attempts.GetValueOrDefault(w), (double)w.Busy / w.Capacity));
            if (worker is null) return null;
            worker.Busy++;
            attempts[worker] = attempts.GetValueOrDefault(worker) + 1;
            return worker;
        }
    }

    private static JsonNode Unpack(ChunkReply reply) => reply.ErrorKind switch
    {
        null => JsonNode.Parse(reply.Result ?? throw new BridgeException("a worker replied without a result"))!,
        "qsharp" => throw new QSharpException(reply.Message ?? "(no message)", reply.Code, reply.Location, reply.QSharpStack),
        "request" => throw new BridgeRequestException(reply.Message ?? "(no message)"),
        _ => throw new BridgeException(reply.Message ?? "(no message)"),
    };

    private static string FirstLine(string message) => message.Split('\n', 2)[0].TrimEnd('\r');

    public void Dispose()
    {
        try
        {
            _host.StopAsync().WaitAsync(TimeSpan.FromSeconds(10)).GetAwaiter().GetResult();
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            // Leaving a cluster that is gone: nothing to tell it.
        }
        _host.Dispose();
    }

    private sealed class WorkerLostException(string message) : Exception(message);

    private sealed class Worker(string silo, IChunkWorker grain, int capacity)
    {
        public string Silo { get; } = silo;
        public IChunkWorker Grain { get; } = grain;
        public int Capacity { get; } = Math.Max(1, capacity);
        public int Busy { get; set; }
        public bool Failed { get; set; }
    }
}
