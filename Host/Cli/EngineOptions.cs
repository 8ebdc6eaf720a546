using System.CommandLine;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Output;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Cli;

/// <summary>
/// The options every command that runs searches shares: engine, seed, workers. A command lists the
/// engines it accepts: Grover-level commands take the quantum engines, ray-tracing commands all.
/// </summary>
public sealed class EngineOptions
{
    private static readonly Dictionary<EngineKind, string> Descriptions = new()
    {
        [EngineKind.FullState] = "fullstate (Q# on the QDK full-state simulator; outcomes cannot be seeded)",
        [EngineKind.Gate] = "gate (the gate-level intersection oracle, comparators and all, on the full-state simulator; exact, slow: tiny images)",
        [EngineKind.Analytic] = "analytic (exact outcome distributions sampled in C#; reproducible by seed)",
        [EngineKind.Classical] = "classical (brute force, every primitive tested: the reference)",
        [EngineKind.Bvh] = "bvh (a bounding-volume hierarchy, SAH build: certain like brute force; #C_Int counts box and primitive tests and the build)",
        [EngineKind.Randomized] = "randomized (floor(sqrt N) random primitives per ray, the paper's sec. 6.3)",
    };

    private readonly EngineKind[] _accepted;

    public readonly Option<EngineKind> Engine;

    public readonly Option<ulong> Seed = CommonOptions.Seed("Seed of every classical random choice (QSearch's iteration counts, analytic outcomes, random primitives).");

    public readonly Option<int> Workers = CommonOptions.Workers("Node bridge processes running Q# in parallel (fullstate engine). Default: the core count.");

    public readonly Option<int?> MaxQubits = CommonOptions.MaxQubits($"Refuse, before simulating anything, a circuit wider than this many qubits. Default: fullstate, the widest dense state this machine holds ({SimulatorCapacity.DefaultMaxQubits(BridgePool.DefaultWorkers)} qubits here: about {SimulatorCapacity.BytesPerAmplitude:0} bytes per amplitude in a WebAssembly heap of at most 4 GiB per worker); gate, {GateEngine.DefaultMaxQubits} at peak with library auxiliaries (its states are sparse; `qrt estimate` shows the width).");

    public readonly Option<string?> Noise = new Option<string?>("--noise")
    {
        Description = "Pauli noise after every gate, on each qubit it touches (the QDK's noisy simulator; the analytic engine's depolarizing model): P for P/3 each of X, Y and Z, or px,py,pz. Default 0: the ideal machine.",
        HelpName = "P|px,py,pz",
    }.Must(text => text is not null && NoiseModel.ParsePauli(text, out var problem) is null ? $"--noise: {problem}" : null);

    public readonly Option<string> NoiseOracleOption = new Option<string>("--noise-oracle")
    {
        Description = "Whose circuit the analytic engine's noise model counts: gate-level (default; the oracle a machine would run, which computes every intersection in gates: the circuit `qrt estimate` prices) or lookup (an oracle over intersection answers computed classically beforehand, which leaves out the cost and the noise of computing them).",
        HelpName = "gate-level|lookup",
        DefaultValueFactory = _ => NoiseOracle.GateLevel.Name(),
    }.Must(text => NoiseOracles.Parse(text ?? "") is null ? $"--noise-oracle: '{text}' is neither gate-level nor lookup" : null);

    public readonly Option<double> QubitLoss = new Option<double>("--qubit-loss")
    {
        Description = "Probability that an operation loses a qubit it touches, in [0, 1); a lost qubit reads Zero. Fullstate engines only. Default 0.",
        HelpName = "L",
    }.Must(loss => NoiseModel.LossProblem(loss) is { } problem ? $"--qubit-loss: {problem}" : null);

    public readonly Option<string?> DeviceNoise = CommonOptions.DeviceNoise();

    public readonly Option<string?> ReadoutError = CommonOptions.ReadoutError();

    public readonly Option<FileInfo?> Cluster = CommonOptions.LocalBridgesOrCluster();

    private bool _imagePartsOnCluster;

    /// <summary>
    /// `render`: --cluster also takes the seeded engines' image parts (<see cref="Rendering.RemoteParts"/>), so it serves every engine.
    /// </summary>
    public EngineOptions WithImagePartsOnCluster()
    {
        _imagePartsOnCluster = true;
        Cluster.Description = "Render on the workers of this cluster file (docs/cluster.md): the Q# engines send their chunks there; the seeded engines (analytic, classical, bvh, randomized) their image, as one part or, from 1024x1024 pixels on, in tiles of 512x512, the same image as here. Default: none; local bridges and this process.";
        return this;
    }

    public EngineOptions(EngineKind fallback, params EngineKind[] accepted)
    {
        Engine = new Option<EngineKind>("--engine", "-e")
        {
            Description = "Where searches run: " + string.Join("; ", accepted.Select(k => Descriptions[k])) + ".",
            DefaultValueFactory = _ => fallback,
            HelpName = string.Join('|', accepted.Select(EngineFactory.Name)),
        }.Choices().Must(kind => accepted.Contains(kind) ? null
            : $"--engine {EngineFactory.Name(kind)} is not available here; choose {string.Join(", ", accepted.Select(EngineFactory.Name))}");
        _accepted = accepted;
    }

    /// <summary>
    /// Whose circuit the analytic engine's noise model counts. Given explicitly to another engine it is a usage error: the
    /// fullstate engine runs the lookup oracle and the gate engine the gate-level one.
    /// </summary>
    public NoiseOracle GetNoiseOracle(ParseResult parse)
    {
        var oracle = NoiseOracles.Parse(parse.GetValue(NoiseOracleOption) ?? "") ?? NoiseOracle.GateLevel;
        var given = parse.GetResult(NoiseOracleOption) is { Implicit: false };
        if (given && !parse.GetValue(Engine).ApproximatesNoise)
            throw new UserError($"--noise-oracle: only the analytic engine models the oracle's noise; the fullstate engine runs the lookup oracle and the gate engine the gate-level one");
        return oracle;
    }

    /// <summary>
    /// The engine the options ask for: its kind, <paramref name="search"/> (default QSearch), workers, qubit limit and noise, and
    /// with `render`'s options the oracle its noise model counts and the plan; on local bridges until given others.
    /// </summary>
    public EngineSetup GetSetup(ParseResult parse, QSearchOptions? search = null, NoiseOracle noiseOracle = NoiseOracle.GateLevel, bool idealPlan = false) => new(
        parse.GetValue(Engine), search ?? new QSearchOptions(), parse.GetValue(Workers), parse.GetValue(MaxQubits), GetNoise(parse),
        NoiseOracle: noiseOracle, IdealPlan: idealPlan, Device: GetDevice(parse));

    /// <summary>The noise model a parse result asks for (validated at parse time).</summary>
    public NoiseModel GetNoise(ParseResult parse) => NoiseModel.Of(parse.GetValue(Noise), parse.GetValue(QubitLoss));

    /// <summary>The device model --device-noise and --readout-error ask for, or null when neither is given.</summary>
    public DeviceNoiseModel? GetDevice(ParseResult parse) => CommonOptions.GetDeviceNoise(parse, DeviceNoise, ReadoutError);

    /// <summary>
    /// The cluster's bridges when <c>--cluster</c> names a file and the engine runs Q# (or, after <see cref="WithImagePartsOnCluster"/>,
    /// is seeded); null otherwise (the engine then starts local bridges of its own, or needs none). Connecting fails with one line
    /// and exit code 3.
    /// </summary>
    public BridgePool? StartBridges(ParseResult parse) =>
        parse.GetValue(Cluster) is { } file && parse.GetValue(Engine) is var kind && (kind.RunsQSharp || _imagePartsOnCluster && kind.IsSeedable)
            ? QuantumRayTracing.Cluster.ClusterBridges.Start(file.FullName, parse.GetValue(Workers))
            : null;

    public void AddTo(Command command)
    {
        command.AddOptions(Engine, Seed, Workers);
        if (_accepted.Any(k => k.RunsQSharp)) command.AddOptions(MaxQubits, Cluster);
        if (_accepted.Any(k => k.SearchesWithGrover)) command.AddOptions(Noise, QubitLoss, DeviceNoise, ReadoutError);
    }
}
