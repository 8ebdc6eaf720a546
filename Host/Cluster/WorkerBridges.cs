using System.Collections.Concurrent;
using System.Text.Json.Nodes;
using QuantumRayTracing.Bridge;

namespace QuantumRayTracing.Cluster;

/// <summary>A worker's Node bridges: each request takes an idle bridge, at most one request per bridge.</summary>
public sealed class WorkerBridges : IChunkExecutor, IDisposable
{
    private readonly QSharpBridge[] _all;
    private readonly ConcurrentBag<QSharpBridge> _idle;
    private readonly SemaphoreSlim _slots;

    public WorkerBridges(int bridges, BridgeOptions? options = null)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(bridges, 1);
        _all = Enumerable.Range(0, bridges).Select(_ => new QSharpBridge(options ?? new BridgeOptions())).ToArray();
        _idle = new ConcurrentBag<QSharpBridge>(_all);
        _slots = new SemaphoreSlim(bridges, bridges);
    }

    public int Capacity => _all.Length;

    /// <summary>Starts every bridge (loads the QDK, compiles the Q# sources); returns the qsharp-lang version.</summary>
    public string? Start()
    {
        Parallel.ForEach(_all, bridge => bridge.Version());
        return _all[0].QSharpVersion;
    }

    public async Task<JsonNode> Execute(JsonObject request)
    {
        await _slots.WaitAsync();
        try
        {
            if (!_idle.TryTake(out var bridge)) throw new InvalidOperationException("more concurrent requests than bridges");
            try
            {
                return await Task.Run(() => bridge.Send(request));
            }
            finally
            {
                _idle.Add(bridge);
            }
        }
        finally
        {
            _slots.Release();
        }
    }

    public void Dispose()
    {
        foreach (var bridge in _all) bridge.Dispose();
    }
}
