using System.CommandLine;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Randomness;

namespace QuantumRayTracing.Cli;

/// <summary>The options every command that runs quantum steps shares: engine, seed, workers.</summary>
public sealed class EngineOptions
{
    public readonly Option<EngineKind> Engine = new("--engine", "-e")
    {
        Description = "Where quantum steps run: fullstate (Q# on the QDK full-state simulator; outcomes cannot be seeded) or analytic (exact outcome distributions sampled in C#; reproducible by seed).",
        DefaultValueFactory = _ => EngineKind.FullState,
        HelpName = "fullstate|analytic",
    };

    public readonly Option<ulong> Seed = new("--seed")
    {
        Description = "Seed of every classical random choice (QSearch's iteration counts, analytic outcomes).",
        DefaultValueFactory = _ => 1UL,
    };

    public readonly Option<int> Workers = new("--workers")
    {
        Description = "Node bridge processes running Q# in parallel (fullstate engine). Default: the core count.",
        DefaultValueFactory = _ => BridgePool.DefaultWorkers,
    };

    public EngineOptions() => Workers.AtLeast(1);

    public void AddTo(Command command)
    {
        command.Options.Add(Engine);
        command.Options.Add(Seed);
        command.Options.Add(Workers);
    }

    /// <summary>The engine a parse result asks for; its randomness is the seed's engine stream.</summary>
    public IGroverEngine Create(ParseResult parse) => Create(parse.GetValue(Engine), new SeededRandom(parse.GetValue(Seed)), parse.GetValue(Workers));

    public static IGroverEngine Create(EngineKind kind, SeededRandom root, int workers) => kind switch
    {
        EngineKind.FullState => new FullStateEngine(new BridgePool(workers)),
        EngineKind.Analytic => new AnalyticEngine(root.Fork(RandomStreams.Engine)),
        _ => throw new ArgumentOutOfRangeException(nameof(kind), kind, null),
    };
}
