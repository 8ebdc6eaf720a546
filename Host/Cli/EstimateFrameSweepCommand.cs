using System.CommandLine;
using QuantumRayTracing.Benchmarks;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Estimates;
using QuantumRayTracing.Output;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Generation;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Cli;

/// <summary>
/// `estimate frame-sweep`: whole-frame costs on fault-tolerant machines for Qornell-64 and Depth
/// Complexity 64 at several sizes, and for the Qornell box against N, written as Markdown
/// (docs/hardware.md) with a plot of runtime per frame against N beside it.
/// </summary>
public sealed class EstimateFrameSweepCommand : Command
{
    public const string CommandLine = "qrt estimate frame-sweep";

    private readonly Option<int[]> _sizes = new("--sizes")
    {
        Description = "Image sides of the Qornell-64 and Depth Complexity 64 frames (space-separated).",
        DefaultValueFactory = _ => [32, 128],
        AllowMultipleArgumentsPerToken = true,
    };

    private readonly Option<int[]> _primitives = new("--primitives")
    {
        Description = "Primitive counts N of the Qornell frames against N (space-separated).",
        DefaultValueFactory = _ => QornellBox.Sizes.ToArray(),
        AllowMultipleArgumentsPerToken = true,
    };

    private readonly Option<int> _scalingSize = new("--scaling-size")
    {
        Description = "Image side of the Qornell frames against N.",
        DefaultValueFactory = _ => 32,
    };

    private readonly Option<int> _detailedSize = new("--detailed-size")
    {
        Description = "Image side of the Qornell-64 frame shown pass by pass.",
        DefaultValueFactory = _ => 128,
    };

    private readonly Option<double> _errorBudget = new("--error-budget")
    {
        Description = "The largest probability that a frame fails, shared equally by its Grover runs.",
        DefaultValueFactory = _ => FrameBudget.DefaultFrame,
    };

    private readonly Option<int> _qpus = new("--qpus")
    {
        Description = "Quantum processors of the parallel runtime.",
        DefaultValueFactory = _ => 64,
    };

    private readonly Option<FileInfo?> _output = new("--output", "-o")
    {
        Description = "Write the Markdown report here (e.g. docs/hardware.md), the plot beside it as <report>-runtime-vs-primitives.png. It replaces only files this command wrote. Default: the report is printed only.",
    };

    private readonly Option<ulong> _seed = new("--seed")
    {
        Description = "Seed of every frame's render.",
        DefaultValueFactory = _ => 1UL,
    };

    private readonly EstimateOptions _options = new();

    public EstimateFrameSweepCommand() : base("frame-sweep", "Whole-frame costs on fault-tolerant machines: Qornell-64 and Depth Complexity 64 at several sizes, the Qornell box against N, on every model given, as Markdown with a plot.")
    {
        Options.Add(_sizes);
        Options.Add(_primitives);
        Options.Add(_scalingSize);
        Options.Add(_detailedSize);
        Options.Add(_errorBudget);
        Options.Add(_qpus);
        Options.Add(_output);
        Options.Add(_seed);
        Options.Add(_options.Oracle);
        Options.Add(_options.Models);
        Options.Add(_options.Workers);
        _qpus.Between(1, 1_000_000);
        _scalingSize.Between(1, SceneLoader.MaxImageSide);
        _detailedSize.Between(1, SceneLoader.MaxImageSide);
        _errorBudget.Validators.Add(r =>
        {
            if (r.TryGetValue<double>(out var budget) && FrameBudget.Problem(budget) is { } problem) r.AddError($"--error-budget {problem}");
        });
        _sizes.Validators.Add(r =>
        {
            if (r.TryGetValue<int[]>(out var values) && (values is not { Length: > 0 } || values.Any(s => s < 1 || s > SceneLoader.MaxImageSide)))
                r.AddError($"--sizes: give one or more sides, each 1..{SceneLoader.MaxImageSide}");
        });
        _primitives.Validators.Add(r =>
        {
            if (r.TryGetValue<int[]>(out var values) && (values is not { Length: > 0 } || values.Any(n => !QornellBox.Sizes.Contains(n))))
                r.AddError($"--primitives: each N must be one of the Qornell box's {string.Join(", ", QornellBox.Sizes)}");
        });
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var output = parse.GetValue(_output);
        var report = new GeneratedReport(output?.FullName, GeneratedReport.MarkdownMarker(CommandLine));
        report.EnsureWritable();
        var plotPath = output is null ? null : Path.Combine(output.DirectoryName!, $"{Path.GetFileNameWithoutExtension(output.Name)}-runtime-vs-primitives.png");
        if (plotPath is not null) ImageFiles.EnsureWritable([plotPath], []);

        var models = _options.QubitModels(parse);
        var construction = _options.Construction(parse);
        var budget = parse.GetValue(_errorBudget);
        var qpus = parse.GetValue(_qpus);
        var seed = parse.GetValue(_seed);
        FrameSettings Settings(Scene scene, int size) =>
            new(scene, RenderDefaults.Options(size, size, seed), new QSearchOptions(), construction, models, budget, qpus);
        var qornell64 = Qornell(64);
        var depthComplexity = SceneLoader.Parse(DepthComplexityScene.Build(64).ToJson(), "built-in depth-complexity-64");

        HardwareReport hardware;
        string machine;
        using (var pool = new BridgePool(parse.GetValue(_options.Workers)))
        {
            FrameEstimate Frame(Scene scene, int size)
            {
                var progress = new ConsoleProgress($"{scene.Name}, {size}x{size}");
                var frame = FrameEstimate.Run(Settings(scene, size), pool, progress);
                progress.Finish();
                Console.Error.WriteLine($"{scene.Name}, {size}x{size}: {frame.Recording.Runs.Count} runs, {frame.EstimatorJobs} estimator jobs, render {frame.WallTimes.Render.TotalSeconds:0.0} s, pricing {frame.WallTimes.Pricing.TotalSeconds:0.0} s");
                return frame;
            }
            var frames = new Dictionary<(string, int), FrameEstimate>();
            FrameEstimate Cached(string key, Scene scene, int size)
            {
                if (!frames.TryGetValue((key, size), out var frame)) frames[(key, size)] = frame = Frame(scene, size);
                return frame;
            }
            var sizes = parse.GetValue(_sizes)!;
            var scenes = sizes.Select(s => ("Qornell-64", s, Cached("qornell-64", qornell64, s)))
                .Concat(sizes.Select(s => ("Depth Complexity 64", s, Cached("depth-complexity-64", depthComplexity, s)))).ToArray();
            var scaling = parse.GetValue(_scalingSize);
            var byPrimitives = parse.GetValue(_primitives)!.Order()
                .Select(n => (n, Cached($"qornell-{n}", n == 64 ? qornell64 : Qornell(n), scaling))).ToArray();
            var detailed = Cached("qornell-64", qornell64, parse.GetValue(_detailedSize));
            var paper = EstimateSweep.Subject(4, EstimateSweep.DefaultCoordinateBits) with { Iterations = 1 };
            var device = new ResourceEstimator(pool, models, withCircuits: false).Estimate([(EstimatedCircuits.SearchRun, paper with { Oracle = paper.Oracle with { Construction = construction } })])[0];
            hardware = new HardwareReport(scenes, byPrimitives, scaling, detailed, device);
            var versions = pool.Bridges[0].Version();
            machine = MachineDescription.Describe(versions["qsharp"]?.GetValue<string>(), versions["node"]?.GetValue<string>());
        }

        var arguments = string.Join(' ', Environment.GetCommandLineArgs().Skip(1));
        var text = hardware.Markdown($"dotnet run --project Host -c Release -- {arguments}", machine, plotPath is null ? null : Path.GetFileName(plotPath));
        Console.WriteLine(text);
        report.Write(text);
        if (plotPath is not null)
        {
            var plot = FramePlots.RuntimeAgainstPrimitives($"Runtime per frame, Qornell box, {hardware.ScalingSize}x{hardware.ScalingSize}, one QPU",
                hardware.ByPrimitives.Select(p => p.Primitives).ToArray(),
                models.Select((m, i) => (m.ToString(), (IReadOnlyList<double>)hardware.ByPrimitives.Select(p => p.Frame.Cost.Total.Split[i].SequentialNanoseconds / 1e9).ToArray())).ToArray(),
                hardware.ByPrimitives.Select(p => p.Frame.ClassicalTime(p.Frame.Cost.Total.Name).TotalSeconds).ToArray());
            ImageFiles.Write([(PlotImage.Render(plot), plotPath)]);
        }
        return 0;
    }

    private static Scene Qornell(int primitives) => SceneLoader.Parse(QornellBox.Build(primitives).ToJson(), $"built-in qornell-{primitives}");
}
