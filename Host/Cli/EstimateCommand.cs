using System.CommandLine;
using QuantumRayTracing.Experiments;
using System.CommandLine.Parsing;
using QuantumRayTracing.Engines;

namespace QuantumRayTracing.Cli;

/// <summary>
/// `estimate`: what the gate-level circuits for one ray would cost (<see cref="EstimateRayAction"/>), or with
/// <c>--frame</c> every Grover run of a whole frame (<see cref="EstimateFrameAction"/>). The options of one are
/// refused with the other.
/// </summary>
public sealed class EstimateCommand : Command
{
    internal readonly Argument<FileInfo?> Scene = CommonOptions.SceneFile();

    internal readonly Option<string?> Pixel = CommonOptions.Pixel("the worst case (--worst-case)");

    internal readonly Option<bool> WorstCase = new("--worst-case")
    {
        Description = "The camera ray whose search needs the widest oracle (most peak qubits; ties: most depth bits, then the first pixel in row-major order). The default.",
    };

    internal readonly Option<string?> Size = CommonOptions.RaySize();

    internal readonly Option<int?> Iterations = CommonOptions.Iterations("Grover iterations r of the QSearch run row. Default: ceil(sqrt N), the largest r QSearch draws.", 100_000);

    internal readonly Option<int> Subpixels = new Option<int>("--subpixels")
    {
        Description = "Subpixels of the QSS readout and QCoin step rows (4x4 = 16 in the thesis).",
        DefaultValueFactory = _ => 16,
    }.Between(1, 1024);

    internal readonly Option<int?> CounterBits = CommonOptions.CounterBits("QSS counter register bits.", 10, fallback: 4, shortName: false);

    internal readonly Option<bool> Frame = new("--frame")
    {
        Description = "Price a whole frame instead of one ray: render it with the analytic engine (the same scene, --size, render options and --seed as `render`), record every Grover run, and sum the runs' estimates per pass on every model, beside the classical render's time.",
    };

    internal readonly Option<double> ErrorBudget = CommonOptions.ErrorBudget("With --frame: the largest probability that the whole frame fails, shared equally by its Grover runs (union bound).");

    internal readonly Option<int> Qpus = CommonOptions.Qpus("With --frame: quantum processors running each batch of independent runs in parallel (the runtime is also given on one).", 1);

    internal readonly Option<FileInfo?> Output = CommonOptions.ReportOutput("With --frame: also write the table here, as Markdown, or CSV with --format csv. It replaces only a file this command wrote. Default: the table is printed only.");

    internal readonly Option<FileInfo?> Cluster = CommonOptions.Cluster("With --frame: run the pricing's Resource Estimator jobs on the workers of this cluster file (docs/cluster.md) instead of --workers local bridges. The frame's searches run on the analytic engine on this machine either way. Default: none, local bridges.");

    internal readonly RenderOptionSet Render = new();

    internal readonly QSearchOptionSet QSearch = new();

    internal readonly EngineOptions Engine = new(EngineKind.Analytic, EngineKind.Analytic);

    internal readonly EstimateOptions Estimator = new();

    internal readonly JsonOption Json = new();

    public EstimateCommand() : base("estimate", "Resource estimates of the gate-level oracle, one Grover iteration and a QSearch run for one ray: logical qubits, T, CCZ, measurements, gates by kind and depth, physical qubits and runtime per qubit model. With --frame: what every Grover run of a whole frame costs, per pass.")
    {
        Arguments.Add(Scene);
        this.AddOptions(Pixel, WorstCase, Size, Iterations, Subpixels, CounterBits);
        Estimator.AddTo(this);
        Json.AddTo(this);
        this.AddOptions(Frame, ErrorBudget, Qpus, Output, Cluster, Engine.Seed);
        Render.AddTo(this);
        QSearch.AddTo(this);
        Validators.Add(EnsurePixelNotSpecifiedWithWorstCase);
        Validators.Add(EnsureOneRayOptionsNotSpecifiedWithFrame);
        Validators.Add(EnsureFrameOptionsNotSpecifiedWithoutFrame);
        Subcommands.Add(new EstimateOracleSweepCommand());
        Subcommands.Add(new EstimateFrameSweepCommand());
        SetAction(parse => parse.GetValue(Frame) ? EstimateFrameAction.Run(this, parse) : EstimateRayAction.Run(this, parse));
    }

    /// <summary>The scene and image size asked for, once the JSON file (and what <paramref name="checkOutputs"/> checks) may be written.</summary>
    internal (Scenes.Scene Scene, int Width, int Height) LoadScene(ParseResult parse, Action? checkOutputs = null)
    {
        Json.EnsureWritable(parse, parse.GetValue(Scene) is { } sceneFile ? [sceneFile.FullName] : []);
        checkOutputs?.Invoke();
        var scene = Scenes.Generation.DefaultScene.Load(parse.GetValue(Scene));
        var (width, height) = OptionText.SizeOr(parse.GetValue(Size), scene);
        return (scene, width, height);
    }

    /// <summary>The options that choose and shape one ray's circuits.</summary>
    private IEnumerable<Option> OneRayOptions => [Pixel, WorstCase, Iterations, Subpixels, CounterBits, Estimator.NoCircuit];

    /// <summary>The options of a frame's pricing: its budget and machine, where it runs, and the render it records.</summary>
    private IEnumerable<Option> FrameOptions => new Option[] { ErrorBudget, Qpus, Output, Cluster, Engine.Seed, QSearch.Growth, QSearch.Rule }.Concat(Render.All);

    private void EnsurePixelNotSpecifiedWithWorstCase(CommandResult r)
    {
        if (r.GetResult(Pixel) is not null && r.GetValue(WorstCase)) r.AddError("--pixel and --worst-case choose the ray two ways; give one");
    }

    private void EnsureOneRayOptionsNotSpecifiedWithFrame(CommandResult r)
    {
        if (!r.GetValue(Frame)) return;
        foreach (var option in OneRayOptions.Where(o => r.GetResult(o) is { Implicit: false }))
            r.AddError($"{option.Name} applies to one ray's estimates; --frame prices every run of a frame");
    }

    private void EnsureFrameOptionsNotSpecifiedWithoutFrame(CommandResult r)
    {
        if (r.GetValue(Frame)) return;
        foreach (var option in FrameOptions.Where(o => r.GetResult(o) is { Implicit: false }))
            r.AddError($"{option.Name} needs --frame");
    }
}
