using System.CommandLine;
using System.Globalization;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Cluster;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Estimates;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Output;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using Spectre.Console;
using QuantumRayTracing.Scenes.Generation;

namespace QuantumRayTracing.Cli;

/// <summary>
/// `estimate`: what the gate-level circuits for one ray would cost: the Resource Estimator's logical
/// counts and physical figures, and the gates and depth of the circuit the QDK extracts.
/// </summary>
public sealed class EstimateCommand : Command
{
    private readonly Argument<FileInfo?> _scene = new("scene")
    {
        Description = $"Scene file (see docs/scenes.md). Default: the Qornell box with {DefaultScene.QornellPrimitives} primitives, built in.",
        Arity = ArgumentArity.ZeroOrOne,
    };

    private readonly Option<string?> _pixel = new("--pixel")
    {
        Description = "The camera ray through pixel X,Y (0,0 is the top left) of the image. Default: the worst case (--worst-case).",
        HelpName = "X,Y",
    };

    private readonly Option<bool> _worstCase = new("--worst-case")
    {
        Description = "The camera ray whose search needs the widest oracle (most peak qubits; ties: most depth bits, then the first pixel in row-major order). The default.",
    };

    private readonly Option<string?> _size = new("--size")
    {
        Description = "Image size the camera rays are cast for, WIDTHxHEIGHT or one number. Default: the scene's.",
        HelpName = "WxH",
    };

    private readonly Option<int?> _iterations = new("--iterations", "-r")
    {
        Description = "Grover iterations r of the QSearch run row. Default: ceil(sqrt N), the largest r QSearch draws.",
    };

    private readonly Option<int> _subpixels = new("--subpixels")
    {
        Description = "Subpixels of the QSS readout and QCoin step rows (4x4 = 16 in the thesis).",
        DefaultValueFactory = _ => 16,
    };

    private readonly Option<int> _counterBits = new("--counter-bits")
    {
        Description = "QSS counter register bits.",
        DefaultValueFactory = _ => 4,
    };

    private readonly Option<bool> _frame = new("--frame")
    {
        Description = "Price a whole frame instead of one ray: render it with the analytic engine (the same scene, --size, render options and --seed as `render`), record every Grover run, and sum the runs' estimates per pass on every model, beside the classical render's time.",
    };

    private readonly Option<double> _errorBudget = new("--error-budget")
    {
        Description = "With --frame: the largest probability that the whole frame fails, shared equally by its Grover runs (union bound).",
        DefaultValueFactory = _ => FrameBudget.DefaultFrame,
    };

    private readonly Option<int> _qpus = new("--qpus")
    {
        Description = "With --frame: quantum processors running each batch of independent runs in parallel (the runtime is also given on one).",
        DefaultValueFactory = _ => 1,
    };

    private readonly Option<FileInfo?> _output = new("--output", "-o")
    {
        Description = "With --frame: also write the table here, as Markdown, or CSV with --format csv. It replaces only a file this command wrote. Default: the table is printed only.",
    };

    private readonly Option<FileInfo?> _cluster = new("--cluster")
    {
        Description = "With --frame: run the pricing's Resource Estimator jobs on the workers of this cluster file (docs/cluster.md) instead of --workers local bridges. The frame's searches run on the analytic engine on this machine either way. Default: none, local bridges.",
        HelpName = "file",
    };

    private readonly RenderOptionSet _render = new();

    private readonly QSearchOptionSet _qsearch = new();

    private readonly EngineOptions _engine = new(EngineKind.Analytic, EngineKind.Analytic);

    private readonly EstimateOptions _options = new();

    private readonly JsonOption _json = new();

    public EstimateCommand() : base("estimate", "Resource estimates of the gate-level oracle, one Grover iteration and a QSearch run for one ray: logical qubits, T, CCZ, measurements, gates by kind and depth, physical qubits and runtime per qubit model. With --frame: what every Grover run of a whole frame costs, per pass.")
    {
        Arguments.Add(_scene);
        Options.Add(_pixel);
        Options.Add(_worstCase);
        Options.Add(_size);
        Options.Add(_iterations);
        Options.Add(_subpixels);
        Options.Add(_counterBits);
        _subpixels.Between(1, 1024);
        _counterBits.Between(1, 10);
        _options.AddTo(this);
        _json.AddTo(this);
        Options.Add(_frame);
        Options.Add(_errorBudget);
        Options.Add(_qpus);
        Options.Add(_output);
        Options.Add(_cluster);
        Options.Add(_engine.Seed);
        _render.AddTo(this);
        _qsearch.AddTo(this);
        _qpus.Between(1, 1_000_000);
        _errorBudget.Validators.Add(r =>
        {
            if (r.TryGetValue<double>(out var budget) && FrameBudget.Problem(budget) is { } problem) r.AddError($"--error-budget {problem}");
        });
        _pixel.Validators.Add(r =>
        {
            if (ParsePixel(r.GetValueOrDefault<string?>()) is { Error: { } error }) r.AddError($"--pixel: {error}");
        });
        _size.Validators.Add(r =>
        {
            if (RenderCommand.ParseSize(r.GetValueOrDefault<string?>()) is { Error: { } error }) r.AddError($"--size: {error}");
        });
        _iterations.Validators.Add(r =>
        {
            if (r.TryGetValue<int?>(out var value) && value is < 0 or > 100_000) r.AddError("--iterations must be between 0 and 100000");
        });
        Validators.Add(r =>
        {
            if (r.GetResult(_pixel) is not null && r.GetValue(_worstCase)) r.AddError("--pixel and --worst-case choose the ray two ways; give one");
            var frame = r.GetValue(_frame);
            foreach (var option in new Option[] { _pixel, _worstCase, _iterations, _subpixels, _counterBits, _options.NoCircuit })
                if (frame && r.GetResult(option) is { Implicit: false }) r.AddError($"{option.Name} applies to one ray's estimates; --frame prices every run of a frame");
            foreach (var option in new Option[] { _errorBudget, _qpus, _output, _cluster, _engine.Seed, _qsearch.Growth, _qsearch.Rule }.Concat(_render.All))
                if (!frame && r.GetResult(option) is { Implicit: false }) r.AddError($"{option.Name} needs --frame");
        });
        Subcommands.Add(new EstimateSweepCommand());
        Subcommands.Add(new EstimateFrameSweepCommand());
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        _json.EnsureWritable(parse, parse.GetValue(_scene) is { } sceneFile ? [sceneFile.FullName] : []);
        if (parse.GetValue(_frame)) return ExecuteFrame(parse);
        var scene = DefaultScene.Load(parse.GetValue(_scene));
        var geometry = new SceneGeometry(scene);
        var (width, height) = RenderCommand.ParseSize(parse.GetValue(_size)) is { Size: { } size } ? size : (scene.Width, scene.Height);
        var construction = _options.Construction(parse);
        var (input, label) = ParsePixel(parse.GetValue(_pixel)) is { Pixel: { } pixel }
            ? pixel.X < width && pixel.Y < height
                ? EstimateRay.Pixel(scene, geometry, width, height, pixel.X, pixel.Y, construction)
                : throw new UserError($"--pixel {pixel.X},{pixel.Y} is outside the {width}x{height} image")
            : EstimateRay.WorstCase(scene, geometry, width, height, construction);
        var iterations = parse.GetValue(_iterations) ?? QSearchSchedule.CeilSqrt(geometry.Count);
        var subject = new EstimateSubject(input, iterations, label, parse.GetValue(_subpixels), parse.GetValue(_counterBits));

        var estimator = _options.Create(parse, out var pool);
        IReadOnlyList<CircuitEstimate> estimates;
        using (pool)
        {
            var jobs = EstimatedCircuits.All.Select(c => (c, subject)).ToArray();
            estimates = EstimateProgress.Run(estimator, jobs, "estimating");
        }

        var table = EstimateTable.For($"Resource estimates: {scene.Name}, {label}", estimates, estimator.Models, Context(scene, geometry, subject));
        _options.Write(parse, table);
        _json.Write(parse, EstimateFigures.Of(table, estimates));
        return 0;
    }

    private int ExecuteFrame(ParseResult parse)
    {
        var format = parse.GetValue(_options.Format);
        var output = parse.GetValue(_output);
        var report = new GeneratedReport(output?.FullName, format == ReportFormat.Csv ? $"# generated by `{FrameCommandLine}`" : GeneratedReport.MarkdownMarker(FrameCommandLine));
        report.EnsureWritable();
        var scene = DefaultScene.Load(parse.GetValue(_scene));
        var (width, height) = RenderCommand.ParseSize(parse.GetValue(_size)) is { Size: { } size } ? size : (scene.Width, scene.Height);
        var settings = new FrameSettings(scene, _render.Get(parse, width, height, parse.GetValue(_engine.Seed)), _qsearch.Get(parse),
            _options.Construction(parse), _options.QubitModels(parse), parse.GetValue(_errorBudget), parse.GetValue(_qpus));

        FrameEstimate frame;
        string machine;
        RunPlace pricedOn;
        var cluster = parse.GetValue(_cluster);
        using (var pool = ClusterBridges.Start(cluster?.FullName, parse.GetValue(_options.Workers)))
        {
            var progress = new ConsoleProgress("analytic");
            frame = FrameEstimate.Run(settings, pool, progress);
            progress.Finish();
            pricedOn = pool.Place;
            var versions = pool.Bridges[0].Version();
            machine = Benchmarks.MachineDescription.Describe(versions["qsharp"]?.GetValue<string>(), versions["node"]?.GetValue<string>());
        }
        var table = FrameTable.For(frame, machine, cluster is null ? null : pricedOn.Description);
        _options.Write(parse, table);
        report.Write(format == ReportFormat.Csv ? table.ToCsv() : table.ToMarkdown());
        if (output is not null) AnsiConsole.WriteLine($"wrote {output.FullName}");
        _json.Write(parse, new { frame.Cost, ClassicalSeconds = frame.WallTimes.Classical.TotalSeconds }, _engine, pricedOn);
        return 0;
    }

    private const string FrameCommandLine = "qrt estimate --frame";

    /// <summary>The lines that say what was estimated: scene, ray, registers, construction, r.</summary>
    public static IReadOnlyList<string> Context(Scene scene, SceneGeometry geometry, EstimateSubject subject)
    {
        var table = subject.Oracle.Table;
        var ray = table.Ray;
        var construction = subject.Oracle.Construction;
        return
        [
            $"scene: {scene.Name}: N = {geometry.Count}, {scene.Grid}",
            $"ray: {subject.Label}, origin {ray.Origin}, direction {ray.Direction}; its first search (full range: every depth, every id; marked rows: {table.Marked(subject.Oracle.Window).MarkedCount})",
            $"registers: {geometry.IndexBits} index, {table.CoordinateBits} bits per coordinate, {table.DepthBits} depth bits",
            $"oracle construction: {construction} ({(construction.InPlaneAxes ? "the two in-plane axes" : "all three axes")}, {(construction.BothBounds ? "both bounds loaded at once" : "minimum then maximum in one register")}, {(construction.MeasuredUnload ? "unload by measurement" : "unload by lookup")})",
            $"QSearch run: r = {subject.Iterations.ToString(CultureInfo.InvariantCulture)} iterations",
        ];
    }

    /// <summary>"12,7" → the pixel; null text → no pixel.</summary>
    public static ((int X, int Y)? Pixel, string? Error) ParsePixel(string? text)
    {
        if (text is null) return (null, null);
        var parts = text.Split(',');
        if (parts.Length != 2 || !int.TryParse(parts[0], NumberStyles.None, CultureInfo.InvariantCulture, out var x)
            || !int.TryParse(parts[1], NumberStyles.None, CultureInfo.InvariantCulture, out var y))
            return (null, $"expected X,Y (two non-negative integers), got '{text}'");
        return ((x, y), null);
    }
}
