using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// The engines a soak renders on, each render through <see cref="Renderer"/> as `render`'s, with the fullstate and gate engines on one bridge pool
/// for the whole soak: each render would otherwise start and compile fresh Node bridges, seconds per
/// render. That pool is <paramref name="shared"/> when given (a cluster's, left running), else started here and
/// stopped on disposing.
/// </summary>
public sealed class SoakEngines(int workers, int maxQubits = GateEngine.DefaultMaxQubits, BridgePool? shared = null) : IDisposable
{
    private BridgePool? _pool;

    /// <summary>One render of <paramref name="scene"/> on <paramref name="kind"/>, its randomness from the options' seed.</summary>
    public RenderResult Render(Scene scene, EngineKind kind, RenderOptions options, IRenderProgress? progress) =>
        Renderer.Render(scene, Setup(kind), options, progress);

    // The limit is the gate engine's; fullstate keeps the widest state the machine holds.
    private EngineSetup Setup(EngineKind kind) => new(kind, new QSearchOptions(), workers,
        kind.SimulatesOracleGates ? maxQubits : null, Pool: kind.RunsQSharp ? Pool : null);

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
