using System.CommandLine;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Output;
using QuantumRayTracing.Randomness;
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

    public readonly Option<int?> MaxQubits = new Option<int?>("--max-qubits")
    {
        Description = $"Refuse, before simulating anything, a circuit wider than this many qubits. Default: fullstate, the widest dense state this machine holds ({SimulatorCapacity.DefaultMaxQubits(BridgePool.DefaultWorkers)} qubits here: about {SimulatorCapacity.BytesPerAmplitude:0} bytes per amplitude in a WebAssembly heap of at most 4 GiB per worker); gate, {GateEngine.DefaultMaxQubits} at peak with library auxiliaries (its states are sparse; `qrt estimate` shows the width).",
        HelpName = "qubits",
    }.Between(1, 100_000);

    public readonly Option<string?> Noise = new("--noise")
    {
        Description = "Pauli noise after every gate, on each qubit it touches (the QDK's noisy simulator; the analytic engine's depolarizing model): P for P/3 each of X, Y and Z, or px,py,pz. Default 0: the ideal machine.",
        HelpName = "P|px,py,pz",
    };

    public readonly Option<double> QubitLoss = new("--qubit-loss")
    {
        Description = "Probability that an operation loses a qubit it touches, in [0, 1); a lost qubit reads Zero. Fullstate engines only. Default 0.",
        HelpName = "L",
    };

    public readonly Option<FileInfo?> Cluster = CommonOptions.LocalBridgesOrCluster();

    public EngineOptions(EngineKind fallback, params EngineKind[] accepted)
    {
        _accepted = accepted;
        Engine = new Option<EngineKind>("--engine", "-e")
        {
            Description = "Where searches run: " + string.Join("; ", accepted.Select(k => Descriptions[k])) + ".",
            DefaultValueFactory = _ => fallback,
            HelpName = string.Join('|', accepted.Select(EngineFactory.Name)),
        };
        Engine.Choices();
        Engine.Validators.Add(result =>
        {
            EngineKind kind;
            try
            {
                kind = result.GetValueOrDefault<EngineKind>();
            }
            catch (InvalidOperationException)
            {
                return; // a name that did not parse has its own error
            }
            if (!_accepted.Contains(kind))
                result.AddError($"--engine {EngineFactory.Name(kind)} is not available here; choose {string.Join(", ", _accepted.Select(EngineFactory.Name))}");
        });
        Noise.Validators.Add(result =>
        {
            if (result.TryGetValue<string?>(out var text) && text is not null && NoiseModel.ParsePauli(text, out var problem) is null)
                result.AddError($"--noise: {problem}");
        });
        QubitLoss.Validators.Add(result =>
        {
            if (result.TryGetValue<double>(out var loss) && NoiseModel.LossProblem(loss) is { } problem)
                result.AddError($"--qubit-loss: {problem}");
        });
    }

    /// <summary>The noise model a parse result asks for (validated at parse time).</summary>
    public NoiseModel GetNoise(ParseResult parse)
    {
        var loss = parse.GetValue(QubitLoss);
        if (parse.GetValue(Noise) is not { } text) return loss == 0 ? NoiseModel.None : new NoiseModel(0, 0, 0, loss);
        var (px, py, pz) = NoiseModel.ParsePauli(text, out var problem) ?? throw new UserError($"--noise: {problem}");
        return new NoiseModel(px, py, pz, loss);
    }

    /// <summary>
    /// The cluster's bridges when <c>--cluster</c> names a file and the engine runs Q#; null otherwise (the
    /// engine then starts local bridges of its own). Connecting fails with one line and exit code 3.
    /// </summary>
    public BridgePool? StartBridges(ParseResult parse) =>
        parse.GetValue(Cluster) is { } file && parse.GetValue(Engine).RunsQSharp
            ? QuantumRayTracing.Cluster.ClusterBridges.Start(file.FullName, parse.GetValue(Workers))
            : null;

    public void AddTo(Command command)
    {
        command.AddOptions(Engine, Seed, Workers);
        if (_accepted.Any(k => k.RunsQSharp)) command.Options.Add(MaxQubits);
        if (_accepted.Any(k => k.RunsQSharp)) command.Options.Add(Cluster);
        if (_accepted.Any(k => k.SearchesWithGrover))
        {
            command.AddOptions(Noise, QubitLoss);
        }
    }

    /// <summary>The Grover engine a parse result asks for; its randomness is the seed's engine stream.</summary>
    /// <remarks>A Q# engine runs on <paramref name="pool"/> (<see cref="StartBridges"/>) when given, without stopping it.</remarks>
    public IGroverEngine Create(ParseResult parse, BridgePool? pool = null) =>
        EngineFactory.Create(parse.GetValue(Engine), new SeededRandom(parse.GetValue(Seed)), parse.GetValue(Workers), parse.GetValue(MaxQubits), pool, GetNoise(parse));
}
