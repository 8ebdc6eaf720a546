using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Benchmarks;

/// <summary>
/// The ray searches a soak renders with, one per render, built as `render` builds them
/// (<see cref="HitSearchFactory.Create"/>), with the fullstate and gate engines on one bridge pool
/// for the whole soak: each render would otherwise start and compile fresh Node bridges, seconds per
/// render. That pool is <paramref name="shared"/> when given (a cluster's, left running), else started here and
/// stopped on disposing.
/// </summary>
public sealed class SoakEngines(int workers, int maxQubits = GateEngine.DefaultMaxQubits, BridgePool? shared = null) : IDisposable
{
    private BridgePool? _pool;

    /// <summary>A fresh search for one render on <paramref name="kind"/>, its randomness forked from <paramref name="seed"/>.</summary>
    public IHitSearch Create(EngineKind kind, ulong seed)
    {
        var simulated = kind is EngineKind.FullState or EngineKind.Gate;
        // The limit is the gate engine's; fullstate keeps the widest state the machine holds.
        return HitSearchFactory.Create(kind, new SeededRandom(seed), workers, new QSearchOptions(),
            kind == EngineKind.Gate ? maxQubits : null, simulated ? Pool : null);
    }

    private BridgePool Pool => shared ?? (_pool ??= new BridgePool(workers));

    /// <summary>The qsharp-lang and Node versions of the bridges, or nulls when no simulator ran.</summary>
    public (string? QSharp, string? Node) Versions()
    {
        var pool = shared ?? _pool;
        if (pool is null || pool.Bridges[0].QSharpVersion is null) return (null, null);
        var version = pool.Bridges[0].Version();
        return (version["qsharp"]?.GetValue<string>(), version["node"]?.GetValue<string>());
    }

    public void Dispose() => _pool?.Dispose();
}
