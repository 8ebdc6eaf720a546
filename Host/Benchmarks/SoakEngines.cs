using QuantumRayTracing.Bridge;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Benchmarks;

/// <summary>
/// The ray searches a soak renders with, one per render, built as `render` builds them
/// (<see cref="EngineOptions.CreateHitSearch"/>) except that the fullstate and gate engines share one
/// bridge pool for the whole soak: each render would otherwise start and compile fresh Node bridges,
/// seconds per render. Disposing stops the bridges.
/// </summary>
public sealed class SoakEngines(int workers, int maxQubits = GateEngine.DefaultMaxQubits) : IDisposable
{
    private BridgePool? _pool;

    /// <summary>A fresh search for one render on <paramref name="kind"/>, its randomness forked from <paramref name="seed"/>.</summary>
    public IHitSearch Create(EngineKind kind, ulong seed)
    {
        var root = new SeededRandom(seed);
        return kind switch
        {
            EngineKind.FullState => new QuantumHitSearch(new Lent(new FullStateEngine(Pool)), root.Fork(RandomStreams.Search), new QSearchOptions()),
            EngineKind.Gate => new QuantumHitSearch(new Lent(new GateEngine(Pool, maxQubits: maxQubits)), root.Fork(RandomStreams.Search), new QSearchOptions(), gateLevel: true),
            _ => EngineOptions.CreateHitSearch(kind, root, workers, new QSearchOptions(), maxQubits),
        };
    }

    private BridgePool Pool => _pool ??= new BridgePool(workers);

    /// <summary>The qsharp-lang and Node versions of the bridges, or nulls when no simulator ran.</summary>
    public (string? QSharp, string? Node) Versions()
    {
        if (_pool is null || _pool.Bridges[0].QSharpVersion is null) return (null, null);
        var version = _pool.Bridges[0].Version();
        return (version["qsharp"]?.GetValue<string>(), version["node"]?.GetValue<string>());
    }

    public void Dispose() => _pool?.Dispose();

    /// <summary>An engine over the shared pool that a search may dispose without stopping the bridges.</summary>
    private sealed class Lent(IGroverEngine engine) : IGroverEngine
    {
        public string Name => engine.Name;

        public IReadOnlyList<int> Measure(IReadOnlyList<GroverRequest> requests) => engine.Measure(requests);

        public void Dispose() { }
    }
}
