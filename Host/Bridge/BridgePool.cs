using System.Collections.Concurrent;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Bridge;

/// <summary>
/// One bridge per worker, started on first use. <see cref="ForEach{T}"/> spreads work items over
/// the workers; each item runs on a bridge no other item is using.
/// </summary>
public sealed class BridgePool : IDisposable
{
    private readonly ConcurrentBag<QSharpBridge> _idle = [];
    private readonly List<QSharpBridge> _all = [];

    public BridgePool(int workers, BridgeOptions? options = null)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(workers, 1);
        Workers = workers;
        for (var w = 0; w < workers; w++)
        {
            var bridge = new QSharpBridge(options ?? new BridgeOptions());
            _all.Add(bridge);
            _idle.Add(bridge);
        }
    }

    /// <summary>
    /// <paramref name="workers"/> bridges whose requests <paramref name="remote"/> serves; the pool disposes
    /// <paramref name="owned"/> (the remote's connection) with itself.
    /// </summary>
    public BridgePool(IBridgeTransport remote, int workers, IDisposable? owned = null)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(workers, 1);
        Workers = workers;
        _remote = remote;
        _owned = owned;
        for (var w = 0; w < workers; w++)
        {
            var bridge = new QSharpBridge(remote);
            _all.Add(bridge);
            _idle.Add(bridge);
        }
    }

    private readonly IBridgeTransport? _remote;
    private readonly IDisposable? _owned;

    /// <summary>Where requests go when they do not run on local bridges (a cluster's workers); null for local bridges.</summary>
    public IBridgeTransport? Remote => _remote;

    /// <summary>Where the requests run, for reports: local bridges or a cluster's workers.</summary>
    public RunPlace Place => _remote?.Place ?? RunPlace.LocalBridges(Workers);

    /// <summary><see cref="Place"/> as reports print it.</summary>
    public string Where => Place.Description;

    /// <summary>Default worker count: one per core.</summary>
    public static int DefaultWorkers => Environment.ProcessorCount;

    public int Workers { get; }

    public IReadOnlyList<QSharpBridge> Bridges => _all;

    /// <summary>Requests sent by all bridges so far.</summary>
    public long Requests => _all.Sum(b => b.Requests);

    /// <summary>Time all bridges spent waiting for replies, summed over the workers.</summary>
    public TimeSpan RequestTime => _all.Aggregate(TimeSpan.Zero, (total, b) => total + b.RequestTime);

    /// <summary>Calls <paramref name="work"/> on every item, at most <see cref="Workers"/> at a time, each with a bridge of its own.</summary>
    public void ForEach<T>(IReadOnlyList<T> items, Action<T, QSharpBridge> work)
    {
        var parallel = new ParallelOptions { MaxDegreeOfParallelism = Workers };
        try
        {
            Parallel.ForEach(items, parallel, item =>
            {
                if (!_idle.TryTake(out var bridge))
                    throw new InvalidOperationException("more concurrent work than bridges");
                try
                {
                    work(item, bridge);
                }
                finally
                {
                    _idle.Add(bridge);
                }
            });
        }
        catch (AggregateException e) when (e.InnerExceptions.Count >= 1)
        {
            // Surface the first failure as itself: it carries the bridge's or Q#'s message.
            System.Runtime.ExceptionServices.ExceptionDispatchInfo.Capture(e.InnerExceptions[0]).Throw();
            throw;
        }
    }

    public void Dispose()
    {
        foreach (var bridge in _all) bridge.Dispose();
        _owned?.Dispose();
    }
}
