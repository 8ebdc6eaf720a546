using System.CommandLine;
using System.Globalization;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Output;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Generation;
using Spectre.Console;

namespace QuantumRayTracing.Cli;

/// <summary>
/// `render`: renders a scene on the chosen engine, compares it with the classical reference and
/// prints the paper's table 1 metrics per pass.
/// </summary>
public sealed class RenderCommand : Command
{
    /// <summary>The most area samples or VPLs per point an option accepts.</summary>
    public const int MaxSamples = 4096;

    private readonly Argument<FileInfo?> _scene = new("scene")
    {
        Description = $"Scene file (see docs/scenes.md). Default: the Qornell box with {DefaultScene.QornellPrimitives} primitives, built in.",
        Arity = ArgumentArity.ZeroOrOne,
    };

    private readonly Option<string?> _output = new("--output", "-o")
    {
        Description = "PNG to write. Default: <scene>-<engine>.png in the current directory. An existing file is replaced only if this program wrote it.",
    };

    private readonly Option<string?> _size = new("--size")
    {
        Description = "Image size, WIDTHxHEIGHT or one number for a square. Default: the scene's.",
        HelpName = "WxH",
    };

    private readonly Option<bool> _reference = new("--reference")
    {
        Description = "Also write the classical reference (<output>-reference.png) and a difference image (<output>-difference.png: differing pixels red).",
    };

    private readonly Option<int> _referenceSamples = new("--reference-samples")
    {
        Description = "Area samples and VPLs per point of the converged classical reference the render is also compared with when it samples light (area lights or --vpl); 0 skips it. It costs about this many / --area-samples (or --vpl) times a classical render.",
        DefaultValueFactory = _ => RenderDefaults.ReferenceSamples,
    };

    private readonly RenderOptionSet _render = new();

    private readonly EngineOptions _engine = new(EngineKind.Analytic,
        EngineKind.FullState, EngineKind.Gate, EngineKind.Analytic, EngineKind.Classical, EngineKind.Randomized);

    private readonly QSearchOptionSet _qsearch = new();

    private readonly JsonOption _json = new();

    public RenderCommand() : base("render", "Render a scene with quantum (or classical) ray searches; print cost per pass (paper table 1) and the error against the classical image.")
    {
        Arguments.Add(_scene);
        Options.Add(_output);
        Options.Add(_size);
        Options.Add(_reference);
        Options.Add(_referenceSamples);
        _render.AddTo(this);
        Options.Add(_render.Budget);
        _engine.AddTo(this);
        _referenceSamples.Between(0, MaxSamples);
        _qsearch.AddTo(this);
        _json.AddTo(this);
        _size.Validators.Add(r =>
        {
            if (ParseSize(r.GetValueOrDefault<string?>()) is { Error: { } error }) r.AddError($"--size: {error}");
        });
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var sceneFile = parse.GetValue(_scene);
        var settings = Settings(parse, sceneFile);
        var inputs = sceneFile is null ? Array.Empty<string>() : [sceneFile.FullName];
        ImageFiles.EnsureWritable(settings.Files, inputs);
        _json.EnsureWritable(parse, [.. settings.Files, .. inputs]);
        using var bridges = _engine.StartBridges(parse);
        EngineFactory.CheckNoise(settings.Engine, settings.NoiseModel);

        PrintPlan(settings, RenderPlan.Of(settings));
        var run = RenderRun.Run(settings with { Pool = bridges }, new ConsoleRunProgress());

        var engineName = EngineFactory.Name(settings.Engine);
        var noise = settings.NoiseModel;
        AnsiConsole.WriteLine($"{engineName} ran on {run.RanOn.Description}");
        Print(noise.IsNoiseless ? engineName : $"{engineName} under {EngineFactory.NoiseDescription(settings.Engine, noise)}", run.Figures, settings.SamplesLight, !noise.IsNoiseless);
        _json.Write(parse, run.Figures, _engine, run.RanOn);
        return 0;
    }

    /// <summary>The run the options ask for; the bridges are started after the outputs are checked.</summary>
    private RenderRunSettings Settings(ParseResult parse, FileInfo? sceneFile)
    {
        var scene = DefaultScene.Load(sceneFile);
        var kind = parse.GetValue(_engine.Engine);
        var stem = sceneFile is null ? DefaultScene.Stem : Path.GetFileNameWithoutExtension(sceneFile.Name);
        var (width, height) = ParseSize(parse.GetValue(_size)) is { Size: { } size } ? size : (scene.Width, scene.Height);
        var options = _render.Get(parse, width, height, parse.GetValue(_engine.Seed)) with { Budget = _render.BudgetShare(parse) };
        return new RenderRunSettings(scene, options, kind, _qsearch.Get(parse),
            parse.GetValue(_output) ?? $"{stem}-{EngineFactory.Name(kind)}.png", parse.GetValue(_reference), parse.GetValue(_referenceSamples),
            parse.GetValue(_engine.Workers), parse.GetValue(_engine.MaxQubits), _engine.GetNoise(parse));
    }

    /// <summary>What the run models, printed before it starts.</summary>
    private static void PrintPlan(RenderRunSettings settings, RenderPlan plan)
    {
        var (scene, options) = (settings.Scene, settings.Options);
        AnsiConsole.WriteLine($"{scene.Name}: N = {plan.Primitives} primitives, {LightSummary(scene)}, {options.Width}x{options.Height} pixels, {scene.Grid}");
        if (settings.SamplesLight)
        {
            var converged = settings.Converged;
            AnsiConsole.WriteLine($"sampled light: {(scene.AreaLights.Count > 0 ? $"{options.AreaSamples} shadow rays per point and area light" : "no area lights")}, {(options.Vpl > 0 ? $"{options.Vpl} VPLs per point" : "no indirect light")}; "
                + (settings.WithConverged ? $"converged reference: {converged.AreaSamples} area samples{(options.Vpl > 0 ? $", {converged.Vpl} VPLs" : "")}" : "no converged reference"));
        }
        AnsiConsole.WriteLine($"modelled per search: {plan.IndexQubits} index qubits + {plan.AuxiliaryQubits} auxiliaries, lookup table of {plan.Primitives} rows x {plan.CoordinateBits} coordinate bits per axis");
        if (settings.Engine.SearchesWithGrover)
            AnsiConsole.WriteLine($"noise model: {EngineFactory.NoiseDescription(settings.Engine, settings.NoiseModel)}");
        if (plan.GateRegisters is { } registers)
            AnsiConsole.WriteLine($"gate-level oracle ({OracleConstruction.Default}), centre ray: {registers.RegisterQubits} register qubits ({registers.IndexQubits} index, {1 + registers.BoundRegisters} x {registers.CoordinateQubits} coordinate, {registers.DepthQubits} depth, {registers.FlagQubits} flags, 1 phase), {registers.PeakQubits} at peak with library auxiliaries");
    }

    private static void Print(string engineName, RenderFigures figures, bool sampled, bool noisy)
    {
        AnsiConsole.Write(MetricsTable(engineName, figures));
        var error = figures.Error;
        var sameSamples = sampled ? " with the same samples (search error alone)" : "";
        AnsiConsole.WriteLine($"error against the classical render{sameSamples}: NRMSE {error.Nrmse:P2} (RMS of 8-bit channel differences / reference range), #Dpix {error.DifferentPixels}, %Dpix {error.DifferentShare:P2}");
        // Against the accuracy budget: the expected share the searches allow (docs/accuracy.md) and the measured one.
        var budget = figures.Budget;
        AnsiConsole.WriteLine($"wrong pixels: expected {budget.ExpectedWrongPixels:0.0} ({budget.ExpectedShare:P3}), measured {error.DifferentPixels} ({error.DifferentShare:P3}); "
            + (budget.Share is { } share ? $"budget {share:P1}" : "no budget (its searches run as configured)"));
        if (budget.Exceeded)
            AnsiConsole.WriteLine($"over budget: the expected wrong pixels stay above {budget.Allowed:0.0} after {BudgetRounds.MaxRounds} budget rounds per pass");
        AnsiConsole.WriteLine(noisy
            ? "(expected: an expectation from each search path's ideal miss rate and finds; noise raises the share, docs/noise.md)"
            : "(expected: an expectation from each search path's miss rate and finds)");
        if (figures is { ConvergedError: { } toConverged, ConvergedNoise: { } noise })
            AnsiConsole.WriteLine($"error against the converged classical reference ({figures.ConvergedSamples} samples): NRMSE {toConverged.Nrmse:P2}, #Dpix {toConverged.DifferentPixels}; the classical render with the same samples: NRMSE {noise.Nrmse:P2} (Monte Carlo noise alone)");
        var convergedWall = figures.ConvergedTime is { } convergedTime ? $", converged reference {convergedTime.TotalSeconds:0.00} s" : "";
        AnsiConsole.WriteLine($"wall time: {engineName} {figures.RenderTime.TotalSeconds:0.00} s, classical reference {figures.ReferenceTime.TotalSeconds:0.00} s{convergedWall}");
        AnsiConsole.MarkupLine("[grey]#Eval: conservative counts r + 1 per Grover run with r ≥ 1 (state preparation included), paper counts r (docs/conventions.md); Int/Ray = (#Eval + #C_Int) / #Rays; table rows (eval-rpc: N per ray and pass, built once and kept compact between rounds) are not in Int/Ray.[/]");
        foreach (var path in figures.Written) AnsiConsole.WriteLine($"wrote {path}");
    }

    private static Table MetricsTable(string engine, RenderFigures figures)
    {
        // Passes as columns, measures as rows: fits an 80-column terminal.
        var passes = figures.Passes.Append(figures.Total).ToArray();
        var classical = figures.ClassicalReference;
        var table = new Table().Title($"{engine}: cost per pass (paper table 1)");
        table.AddColumn("measure");
        foreach (var pass in passes) table.AddColumn(new TableColumn(pass.Name).RightAligned());
        void Row(string measure, Func<PassMetrics, string> value) => table.AddRow([measure, .. passes.Select(value)]);
        Row("#Rays", p => N(p.Rays));
        Row("#It", p => p.Iterations.ToString(CultureInfo.InvariantCulture));
        Row("#Eval, conservative", p => N(p.Cost.QueriesConservative));
        Row("#Eval, paper", p => N(p.Cost.QueriesPaper));
        Row("#C_Int", p => N(p.Cost.ClassicalTests));
        Row("#Int, conservative", p => N(p.IntersectionsConservative));
        Row("Int/Ray, conservative", p => p.PerRayConservative.ToString("0.00", CultureInfo.InvariantCulture));
        Row("Int/Ray, paper", p => p.PerRayPaper.ToString("0.00", CultureInfo.InvariantCulture));
        Row("#Cpix (neighbours)", p => N(p.UpdatedPixels));
        Row("settled classically", p => N(p.SettledRays));
        Row("table rows (eval-rpc)", p => N(p.TableRows));
        Row("wall time", p => $"{p.Elapsed.TotalSeconds:0.00} s");
        table.Caption($"classical reference: {N(classical.Rays)} rays, Int/Ray {classical.PerRayConservative:0.00}");
        return table;
    }

    private static string LightSummary(Scene scene)
    {
        var kinds = new[] { (scene.Lights.Count, "point"), (scene.AreaLights.Count, "area"), (scene.DirectionalLights.Count, "directional") }
            .Where(k => k.Item1 > 0).Select(k => $"{k.Item1} {k.Item2}").ToArray();
        return kinds.Length == 0 ? "no lights" : "lights: " + string.Join(", ", kinds);
    }

    private static string N(long value) => value.ToString("N0", CultureInfo.InvariantCulture);

    /// <summary>"128" or "160x120" → the size; null text → no size.</summary>
    public static ((int Width, int Height)? Size, string? Error) ParseSize(string? text)
    {
        if (text is null) return (null, null);
        var parts = text.Split('x', 'X');
        if (parts.Length > 2 || parts.Any(p => !int.TryParse(p, NumberStyles.None, CultureInfo.InvariantCulture, out _)))
            return (null, $"expected WIDTHxHEIGHT or one number, got '{text}'");
        var width = int.Parse(parts[0], CultureInfo.InvariantCulture);
        var height = parts.Length == 2 ? int.Parse(parts[1], CultureInfo.InvariantCulture) : width;
        if (width < 1 || height < 1 || width > SceneLoader.MaxImageSide || height > SceneLoader.MaxImageSide)
            return (null, $"each side must be 1..{SceneLoader.MaxImageSide}, got {width}x{height}");
        return ((width, height), null);
    }
}
