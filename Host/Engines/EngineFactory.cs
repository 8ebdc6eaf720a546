using QuantumRayTracing.Bridge;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Output;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Scenes;
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

    /// <summary>The ray search of <paramref name="engine"/> (<see cref="CreateSearch(EngineKind, SeededRandom, int, QSearchOptions, int?, BridgePool?, NoiseModel?, DepolarizingApproximation?, bool, DeviceNoiseModel?)"/>).</summary>
    public static IHitSearch CreateSearch(EngineSetup engine, SeededRandom root, DepolarizingApproximation? approximation = null) =>
        CreateSearch(engine.Kind, root, engine.Workers, engine.Search, engine.MaxQubits, engine.Pool, engine.Noise, approximation, engine.IdealPlan, engine.Device);

    /// <summary>
    /// The ray search of <paramref name="kind"/>: QSearch over its Grover engine, or a classical search. The
    /// noise model is the caller's to check (<see cref="CheckNoise"/>), once per run.
    /// </summary>
    /// <remarks>
    /// Under noise with an approximation, the search's miss rates take the noisy runs' success: those the passes plan with, unless
    /// <paramref name="idealPlan"/>, and always those the expected wrong pixels are reported with.
    /// </remarks>
    public static IHitSearch CreateSearch(EngineKind kind, SeededRandom root, int workers, QSearchOptions options, int? maxQubits = null, BridgePool? pool = null, NoiseModel? noise = null,
        DepolarizingApproximation? approximation = null, bool idealPlan = false, DeviceNoiseModel? device = null)
    {
        noise ??= NoiseModel.None;
        var noisy = !noise.IsNoiseless || device is { IsNoiseless: false };
        var noisySuccess = approximation is not null && noisy ? device is null ? approximation.NoisySuccess(noise) : approximation.NoisySuccess(CircuitRates.Of(device)) : null;
        return kind.SearchesWithGrover
            ? new QuantumHitSearch(Grover(kind, root, workers, maxQubits, pool, noise, approximation, device), root.Fork(RandomStreams.Search), options, gateLevel: kind.SimulatesOracleGates,
                success: idealPlan ? null : noisySuccess, machineSuccess: noisySuccess, pooled: kind == EngineKind.Analytic && !noisy)
            : kind switch
            {
                EngineKind.Classical => new ClassicalHitSearch(),
                EngineKind.Bvh => new BvhHitSearch(),
                _ => new RandomizedHitSearch(root.Fork(RandomStreams.Engine)),
            };
    }

    /// <summary>The Grover engine of <paramref name="engine"/>, its noise model checked (<see cref="Create(EngineKind, SeededRandom, int, int?, BridgePool?, NoiseModel?, DeviceNoiseModel?)"/>).</summary>
    public static IGroverEngine Create(EngineSetup engine, SeededRandom root) =>
        Create(engine.Kind, root, engine.Workers, engine.MaxQubits, engine.Pool, engine.NoiseModel, engine.Device);

    /// <summary>
    /// A Grover engine, its noise model checked; <paramref name="maxQubits"/> null keeps the engine's own limit. The Q# engines
    /// start bridges of their own, or use <paramref name="pool"/> without stopping it when they are disposed.
    /// </summary>
    public static IGroverEngine Create(EngineKind kind, SeededRandom root, int workers, int? maxQubits = null, BridgePool? pool = null, NoiseModel? noise = null, DeviceNoiseModel? device = null)
    {
        noise ??= NoiseModel.None;
        CheckNoise(kind, noise, device);
        return Grover(kind, root, workers, maxQubits, pool, noise, device: device);
    }

    private static IGroverEngine Grover(EngineKind kind, SeededRandom root, int workers, int? maxQubits, BridgePool? pool, NoiseModel noise, DepolarizingApproximation? approximation = null,
        DeviceNoiseModel? device = null) => kind switch
    {
        EngineKind.FullState => new FullStateEngine(pool ?? new BridgePool(workers), maxQubits: maxQubits, ownsPool: pool is null, noise: noise,
            device: device is { IsNoiseless: false } ? device : null, readoutRandom: root.Fork(RandomStreams.Engine)),
        EngineKind.Gate => new GateEngine(pool ?? new BridgePool(workers), maxQubits: maxQubits ?? GateEngine.DefaultMaxQubits, ownsPool: pool is null, noise: noise),
        EngineKind.Analytic => new AnalyticEngine(root.Fork(RandomStreams.Engine), noise, approximation, device),
        _ => throw new ArgumentOutOfRangeException(nameof(kind), kind, "not a Grover engine"),
    };

    /// <summary>
    /// The noise model as results on <paramref name="kind"/> name it: the analytic engine adds its approximation and the
    /// oracle it counts (the lookup oracle's when none is given), the simulators the oracle they run.
    /// </summary>
    public static string NoiseDescription(EngineKind kind, NoiseModel noise, DepolarizingApproximation? approximation = null, DeviceNoiseModel? device = null) =>
        device is not null ? kind.ApproximatesNoise ? (approximation ?? DepolarizingApproximation.Default).Description(device)
            : $"{device.Description()}, on the {(kind.SimulatesOracleGates ? NoiseOracle.GateLevel : NoiseOracle.Lookup).Description()}"
        : kind.ApproximatesNoise ? (approximation ?? DepolarizingApproximation.Default).Description(noise)
        : noise.IsNoiseless || !kind.SearchesWithGrover ? noise.Description()
        : $"{noise.Description()}, on the {(kind.SimulatesOracleGates ? NoiseOracle.GateLevel : NoiseOracle.Lookup).Description()}";

    /// <summary>
    /// The analytic engine's approximation for renders of <paramref name="scene"/>: over the gate-level oracle's traced
    /// circuit of the scene's shape, or the lookup oracle's locations. A shape the table lacks is a usage error naming the option.
    /// </summary>
    public static DepolarizingApproximation Approximation(NoiseOracle oracle, Scenes.Scene scene)
    {
        if (oracle == NoiseOracle.Lookup) return DepolarizingApproximation.Default;
        if (scene.Primitives.Any(p => p is not Rectangle))
            throw new UserError($"--noise-oracle gate-level: the gate-level oracle takes rectangles only, and {scene.Name} holds triangles, so no traced circuit is theirs; use --noise-oracle lookup");
        var traced = GateLevelExposureTable.For(scene) ?? throw new UserError(
            $"--noise-oracle gate-level: the gate-level circuit of {scene.Name} ({GateLevelExposure.KeyOf(scene)}) is not among the traced shapes ({string.Join("; ", GateLevelExposureTable.Keys)}); trace it with `qrt bench noise --parts exposure`, or use --noise-oracle lookup");
        return new DepolarizingApproximation(GateLevel: traced);
    }

    /// <summary>
    /// Refuses, before any work, a scene whose primitives the engine cannot search: one line naming the scene, the engine
    /// and what it takes.
    /// </summary>
    public static void CheckPrimitives(EngineKind kind, Scene scene)
    {
        if (kind.TakesAnyPrimitive) return;
        var others = scene.Primitives.Count(p => p is not Rectangle);
        if (others > 0)
            throw new UserError($"scene {scene.Name}: the {kind.Name} engine's gate-level oracle takes rectangles only, and the scene holds {others} other primitives (triangles); use --engine analytic, fullstate, classical or bvh");
    }

    /// <summary>
    /// Refuses, as a usage error naming the option, a noise model the engine cannot run; with <paramref name="count"/>, the N its
    /// searches run over.
    /// </summary>
    public static void CheckNoise(EngineKind kind, NoiseModel noise, DeviceNoiseModel? device = null, int? count = null)
    {
        if (device is not null)
        {
            if (!noise.IsNoiseless) throw new UserError("--noise and --device-noise/--readout-error: give one noise model, not both");
            if (!kind.SearchesWithGrover) throw new UserError($"--device-noise/--readout-error: the {Name(kind)} engine runs no quantum circuit");
            if (!kind.RunsDeviceNoise) throw new UserError($"--device-noise/--readout-error: {DeviceNoiseUnsupported(kind)}");
            if (kind == EngineKind.FullState && count is { } n && !System.Numerics.BitOperations.IsPow2(n))
                throw new UserError($"--device-noise/--readout-error: the fullstate engine runs a device model over N a power of two (its preparation is then one H per index qubit), not N = {n}; use --engine analytic");
        }
        if (noise.QubitLoss > 0 && !kind.ModelsQubitLoss)
            throw new UserError(kind.SimulatesOracleGates ? $"--qubit-loss: {GateEngine.LossUnsupported}" : $"--qubit-loss: the {Name(kind)} engine does not model qubit loss (its depolarizing approximation covers Pauli noise); use --engine fullstate");
        if (!noise.IsNoiseless && !kind.SearchesWithGrover)
            throw new UserError($"--noise: the {Name(kind)} engine runs no quantum circuit");
    }

    /// <summary>Why <paramref name="kind"/> cannot run a device model.</summary>
    private static string DeviceNoiseUnsupported(EngineKind kind) =>
        $"the {Name(kind)} engine runs one Pauli rate on every gate (--noise); a device model runs on the analytic and fullstate engines";

    /// <summary>Where a Q# engine's work runs, for reports: the cluster's workers or this machine.</summary>
    public static string Where(EngineKind kind, BridgePool? bridges, int workers) => Place(kind, bridges, workers).Description;

    /// <summary><see cref="Where"/> for scripts (<c>--json</c>): local or cluster, bridges and workers.</summary>
    /// <remarks>Without <paramref name="bridges"/> a Q# engine starts <paramref name="workers"/> local bridges of its own.</remarks>
    /// <remarks>A seeded engine given a cluster's bridges renders its image parts on the cluster's workers.</remarks>
    public static RunPlace Place(EngineKind kind, BridgePool? bridges, int workers) =>
        kind.RunsQSharp ? bridges?.Place ?? RunPlace.LocalBridges(workers)
        : kind.IsSeedable && bridges?.Remote is not null ? bridges.Place : RunPlace.NoBridges;
}
