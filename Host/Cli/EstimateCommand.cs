using System.CommandLine;
using QuantumRayTracing.Experiments;
using System.CommandLine.Parsing;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Estimates;
using QuantumRayTracing.Output;
using Spectre.Console;

namespace QuantumRayTracing.Cli;

/// <summary>
/// `estimate`: what the gate-level circuits for one ray would cost (options → <see cref="RayEstimateSettings"/> →
/// <see cref="RayEstimateRun"/>), or with <c>--frame</c> every Grover run of a whole frame per pass (options →
/// <see cref="FrameSettings"/> → <see cref="FrameEstimateRun"/>). The options of one are refused with the other.
/// </summary>
public sealed class EstimateCommand : Command
{
    private const string FrameCommandText = "qrt estimate --frame";

    private readonly Argument<FileInfo?> _scene = CommonOptions.SceneFile();

    private readonly Option<string?> _pixel = CommonOptions.Pixel("the worst case (--worst-case)");

    private readonly Option<bool> _worstCase = new("--worst-case")
    {
        Description = "The camera ray whose search needs the widest oracle (most peak qubits; ties: most depth bits, then the first pixel in row-major order). The default.",
    };

    private readonly Option<string?> _size = CommonOptions.RaySize();

    private readonly Option<int?> _iterations = CommonOptions.Iterations("Grover iterations r of the QSearch run row. Default: ceil(sqrt N), the largest r QSearch draws.", 100_000);

    private readonly Option<int> _subpixels = new Option<int>("--subpixels")
    {
        Description = "s: the QSS readout and QCoin step rows average s x s subpixels, as `supersample --subpixels` (4: 16 subpixels, as in the thesis).",
        DefaultValueFactory = _ => 4,
    }.Between(1, 32);

    private readonly Option<int?> _counterBits = CommonOptions.CounterBits("QSS counter register bits.", 10, fallback: 4, shortName: false);

    private readonly Option<int?> _pooled = new Option<int?>("--pooled")
    {
        Description = "Price a pooled search's query and Grover iteration for a pool of R camera rays of the image (spread evenly over it, each its first search), beside the one ray's oracle and iteration, instead of the one-ray rows. A pooled budget round searches all its rays' (ray, primitive) pairs with one QSearch; its lookups are over R x N pairs. Default: none, the one ray's circuits alone.",
        HelpName = "R",
    }.Between(1, 2048);

    private readonly Option<bool> _frame = new("--frame")
    {
        Description = "Price a whole frame instead of one ray: render it with the analytic engine (the same scene, --size, render options and --seed as `render`), record every Grover run, and sum the runs' estimates per pass on every model, beside the classical render's time.",
    };

    private readonly Option<double> _errorBudget = CommonOptions.ErrorBudget("With --frame: the largest probability that the whole frame fails, shared equally by its Grover runs (union bound).");

    private readonly Option<int> _qpus = CommonOptions.Qpus("With --frame: quantum processors running each batch of independent runs in parallel (the runtime is also given on one).", 1);

    private readonly Option<FileInfo?> _output = CommonOptions.ReportOutput("With --frame: also write the table here, as Markdown, or CSV with --format csv. It replaces only a file this command wrote. Default: the table is printed only.");

    private readonly Option<FileInfo?> _cluster = CommonOptions.Cluster("With --frame: run the pricing's Resource Estimator jobs on the workers of this cluster file (docs/cluster.md) instead of --workers local bridges. The frame's searches run on the analytic engine on this machine either way. Default: none, local bridges.");

    private readonly RenderOptionSet _render = new();

    private readonly QSearchOptionSet _qsearch = new();

    private readonly EngineOptions _engine = new(EngineKind.Analytic, EngineKind.Analytic);

    private readonly EstimateOptions _estimator = new();

    private readonly JsonOption _json = new();

    public EstimateCommand() : base("estimate", "Resource estimates of the gate-level oracle, one Grover iteration and a QSearch run for one ray: logical qubits, T, CCZ, measurements, gates by kind and depth, physical qubits and runtime per qubit model. With --frame: what every Grover run of a whole frame costs, per pass.")
    {
        Arguments.Add(_scene);
        this.AddOptions(_pixel, _worstCase, _size, _iterations, _subpixels, _counterBits, _pooled);
        _estimator.AddTo(this);
        _json.AddTo(this);
        this.AddOptions(_frame, _errorBudget, _qpus, _output, _cluster, _engine.Seed);
        _render.AddTo(this);
        _qsearch.AddTo(this);
        Validators.Add(EnsurePixelNotSpecifiedWithWorstCase);
        Validators.Add(EnsureOptionsFitOneRayOrFrame);
        Subcommands.Add(new EstimateOracleSweepCommand());
        Subcommands.Add(new EstimateFrameSweepCommand());
        SetAction(parse => parse.GetValue(_frame) ? EstimateFrame(parse) : EstimateRay(parse));
    }

    private int EstimateRay(ParseResult parse)
    {
        var (scene, width, height) = LoadScene(parse);
        var pixel = parse.GetValue(_pixel) is { } text ? OptionText.PixelIn(text, width, height) : ((int, int)?)null;
        if (parse.GetValue(_pooled) > (long)width * height)
            throw new UserError($"--pooled: a pool of {parse.GetValue(_pooled)} rays, but a {width}x{height} image casts {width * height} camera rays");
        var (table, estimates) = RayEstimateRun.Run(new RayEstimateSettings(scene, width, height, pixel, parse.GetValue(_iterations), parse.GetValue(_subpixels) * parse.GetValue(_subpixels),
            parse.GetValue(_counterBits)!.Value, _estimator.Construction(parse), _estimator.QubitModels(parse), !parse.GetValue(_estimator.NoCircuit), parse.GetValue(_estimator.Workers),
            parse.GetValue(_pooled)));
        table.Write(parse.GetValue(_estimator.Format));
        _json.Write(parse, EstimateFigures.Of(table, estimates));
        return ExitCodes.Success;
    }

    private int EstimateFrame(ParseResult parse)
    {
        var (format, output) = (parse.GetValue(_estimator.Format), parse.GetValue(_output));
        var report = new GeneratedReport(output?.FullName, format == ReportFormat.Csv ? $"# generated by `{FrameCommandText}`" : GeneratedReport.MarkdownMarker(FrameCommandText));
        var (scene, width, height) = LoadScene(parse, report.EnsureWritable);
        var settings = new FrameSettings(scene, _render.Get(parse, width, height, parse.GetValue(_engine.Seed)), _qsearch.Get(parse),
            _estimator.Construction(parse), _estimator.QubitModels(parse), parse.GetValue(_errorBudget), parse.GetValue(_qpus));
        var run = FrameEstimateRun.Run(settings, parse.GetValue(_cluster)?.FullName, parse.GetValue(_estimator.Workers));
        run.Table.Write(format);
        report.Write(format == ReportFormat.Csv ? run.Table.ToCsv() : run.Table.ToMarkdown());
        if (output is not null) AnsiConsole.WriteLine($"wrote {output.FullName}");
        _json.Write(parse, new { run.Frame.Cost, ClassicalSeconds = run.Frame.WallTimes.Classical.TotalSeconds }, _engine, run.PricedOn);
        return ExitCodes.Success;
    }

    /// <summary>The scene and image size asked for, once the JSON file (and what <paramref name="checkOutputs"/> checks) may be written.</summary>
    private (Scenes.Scene Scene, int Width, int Height) LoadScene(ParseResult parse, Action? checkOutputs = null)
    {
        _json.EnsureWritable(parse, parse.GetValue(_scene) is { } sceneFile ? [sceneFile.FullName] : []);
        checkOutputs?.Invoke();
        var scene = Scenes.Generation.DefaultScene.Load(parse.GetValue(_scene));
        if (scene.Primitives.Any(p => p is not Scenes.Rectangle))
            throw new UserError($"scene {scene.Name}: estimate prices the gate-level oracle, which takes rectangles only, and the scene holds triangles");
        var (width, height) = OptionText.SizeOr(parse.GetValue(_size), scene);
        return (scene, width, height);
    }

    /// <summary>The options that choose and shape one ray's circuits.</summary>
    private IEnumerable<Option> OneRayOptions => [_pixel, _worstCase, _iterations, _subpixels, _counterBits, _estimator.NoCircuit, _pooled];

    /// <summary>The options of a frame's pricing: its budget and machine, where it runs, and the render it records.</summary>
    private IEnumerable<Option> FrameOptions => new Option[] { _errorBudget, _qpus, _output, _cluster, _engine.Seed, _qsearch.Growth, _qsearch.Rule }.Concat(_render.All);

    private void EnsurePixelNotSpecifiedWithWorstCase(CommandResult r)
    {
        if (r.GetResult(_pixel) is not null && r.GetValue(_worstCase)) r.AddError("--pixel and --worst-case choose the ray two ways; give one");
    }

    private void EnsureOptionsFitOneRayOrFrame(CommandResult r)
    {
        var frame = r.GetValue(_frame);
        foreach (var option in (frame ? OneRayOptions : FrameOptions).Where(o => r.GetResult(o) is { Implicit: false }))
            r.AddError(frame ? $"{option.Name} applies to one ray's estimates; --frame prices every run of a frame" : $"{option.Name} needs --frame");
    }
}
