using QuantumRayTracing.Bridge;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Output;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Search;
using QuantumRayTracing.Search.Bvh;

namespace QuantumRayTracing.Engines;

/// <summary>
/// The engines by kind: the ray search a render uses, the Grover engine under it, the noise each can run and
/// where their work runs. The one place commands, runs and experiments create them, so an engine is wired the
/// same way everywhere.
/// </summary>
public static class EngineFactory
{
    public static string Name(EngineKind kind) => kind.Name;

    /// <summary>
    /// The ray search of <paramref name="kind"/>: QSearch over its Grover engine, or a classical search. The
    /// noise model is the caller's to check (<see cref="CheckNoise"/>), once per run.
    /// </summary>
    public static IHitSearch CreateSearch(EngineKind kind, SeededRandom root, int workers, QSearchOptions options, int? maxQubits = null, BridgePool? pool = null, NoiseModel? noise = null) =>
        kind.SearchesWithGrover
            ? new QuantumHitSearch(Grover(kind, root, workers, maxQubits, pool, noise ?? NoiseModel.None), root.Fork(RandomStreams.Search), options, gateLevel: kind.SimulatesOracleGates)
            : kind switch
            {
                EngineKind.Classical => new ClassicalHitSearch(),
                EngineKind.Bvh => new BvhHitSearch(),
                _ => new RandomizedHitSearch(root.Fork(RandomStreams.Engine)),
            };

    /// <summary>
    /// A Grover engine, its noise model checked; <paramref name="maxQubits"/> null keeps the engine's own limit. The Q# engines
    /// start bridges of their own, or use <paramref name="pool"/> without stopping it when they are disposed.
    /// </summary>
    public static IGroverEngine Create(EngineKind kind, SeededRandom root, int workers, int? maxQubits = null, BridgePool? pool = null, NoiseModel? noise = null)
    {
        noise ??= NoiseModel.None;
        CheckNoise(kind, noise);
        return Grover(kind, root, workers, maxQubits, pool, noise);
    }

    private static IGroverEngine Grover(EngineKind kind, SeededRandom root, int workers, int? maxQubits, BridgePool? pool, NoiseModel noise) => kind switch
    {
        EngineKind.FullState => new FullStateEngine(pool ?? new BridgePool(workers), maxQubits: maxQubits, ownsPool: pool is null, noise: noise),
        EngineKind.Gate => new GateEngine(pool ?? new BridgePool(workers), maxQubits: maxQubits ?? GateEngine.DefaultMaxQubits, ownsPool: pool is null, noise: noise),
        EngineKind.Analytic => new AnalyticEngine(root.Fork(RandomStreams.Engine), noise),
        _ => throw new ArgumentOutOfRangeException(nameof(kind), kind, "not a Grover engine"),
    };

    /// <summary>The noise model as results on <paramref name="kind"/> name it: the analytic engine adds its approximation.</summary>
    public static string NoiseDescription(EngineKind kind, NoiseModel noise) =>
        kind.ApproximatesNoise ? DepolarizingApproximation.Default.Description(noise) : noise.Description();

    /// <summary>Refuses, as a usage error naming the option, a noise model the engine cannot run.</summary>
    public static void CheckNoise(EngineKind kind, NoiseModel noise)
    {
        if (noise.QubitLoss > 0 && !kind.ModelsQubitLoss)
            throw new UserError(kind.SimulatesOracleGates ? $"--qubit-loss: {GateEngine.LossUnsupported}" : $"--qubit-loss: the {Name(kind)} engine does not model qubit loss (its depolarizing approximation covers Pauli noise); use --engine fullstate");
        if (!noise.IsNoiseless && !kind.SearchesWithGrover)
            throw new UserError($"--noise: the {Name(kind)} engine runs no quantum circuit");
    }

    /// <summary>Where a Q# engine's work runs, for reports: the cluster's workers or this machine.</summary>
    public static string Where(EngineKind kind, BridgePool? bridges, int workers) => Place(kind, bridges, workers).Description;

    /// <summary><see cref="Where"/> for scripts (<c>--json</c>): local or cluster, bridges and workers.</summary>
    /// <remarks>Without <paramref name="bridges"/> a Q# engine starts <paramref name="workers"/> local bridges of its own.</remarks>
    public static RunPlace Place(EngineKind kind, BridgePool? bridges, int workers) =>
        kind.RunsQSharp ? bridges?.Place ?? RunPlace.LocalBridges(workers) : RunPlace.NoBridges;
}
