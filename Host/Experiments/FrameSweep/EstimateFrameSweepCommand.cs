using System.CommandLine;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Estimates;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Scenes.Generation;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Experiments;

/// <summary>`estimate frame-sweep`: options → <see cref="FrameSweepSettings"/> → <see cref="FrameSweepExperiment"/> (docs/frame-sweep.md, with a plot of runtime per frame against N).</summary>
public sealed class EstimateFrameSweepCommand : Command
{
    public const string CommandText = "qrt estimate frame-sweep";

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

    private readonly Option<int> _scalingSize = new Option<int>("--scaling-size") { Description = "Image side of the Qornell frames against N.", DefaultValueFactory = _ => 32 }
        .Between(1, SceneLoader.MaxImageSide);

    private readonly Option<int> _detailedSize = new Option<int>("--detailed-size") { Description = "Image side of the Qornell-64 frame shown pass by pass.", DefaultValueFactory = _ => 128 }
        .Between(1, SceneLoader.MaxImageSide);

    private readonly Option<double> _errorBudget = CommonOptions.ErrorBudget("The largest probability that a frame fails, shared equally by its Grover runs.");

    private readonly Option<int> _qpus = CommonOptions.Qpus("Quantum processors of the parallel runtime.", 64);

    private readonly Option<FileInfo?> _output = CommonOptions.ReportOutput("Write the Markdown report here (e.g. docs/frame-sweep.md), the plot beside it as <report>-runtime-vs-primitives.png. It replaces only files this command wrote. Default: the report is printed only.");

    private readonly Option<ulong> _seed = CommonOptions.Seed("Seed of every frame's render.");

    private readonly EstimateOptions _options = new();

    public EstimateFrameSweepCommand() : base("frame-sweep", "Whole-frame costs on fault-tolerant machines: Qornell-64 and Depth Complexity 64 at several sizes, the Qornell box against N, on every model given, as Markdown with a plot.")
    {
        this.AddOptions(_sizes, _primitives, _scalingSize, _detailedSize, _errorBudget, _qpus, _output, _seed, _options.Oracle, _options.Models, _options.Workers);
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
        var writer = new ReportWriter(parse.GetValue(_output)?.FullName, CommandText);
        writer.EnsureWritable(FrameSweepExperiment.Pictures);
        var versions = ToolVersions.Detect();
        var machine = MachineDescription.Describe(versions.QsharpLang, versions.Node);
        var settings = new FrameSweepSettings(parse.GetValue(_sizes)!, parse.GetValue(_primitives)!, parse.GetValue(_scalingSize), parse.GetValue(_detailedSize),
            parse.GetValue(_seed), _options.Construction(parse), _options.QubitModels(parse), parse.GetValue(_errorBudget), parse.GetValue(_qpus), parse.GetValue(_options.Workers), machine);
        var report = FrameSweepExperiment.Run(settings, Console.Error.WriteLine);
        writer.Write(report, ReportFooter.Lines(machine));
        return ExitCodes.Success;
    }
}
