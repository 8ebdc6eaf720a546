using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Metrics;
using QuantumRayTracing.Output;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Generation;
using QuantumRayTracing.Search;
using Spectre.Console;

namespace QuantumRayTracing.Cli;

/// <summary>
/// `render`: renders a scene on the chosen engine, compares it with the classical reference and
/// prints the paper's table 1 metrics per pass.
/// </summary>
public sealed class RenderCommand : Command
{
    /// <summary>The scene rendered when none is named: the paper's figure 1.</summary>
    public const int DefaultQornellPrimitives = 64;

    /// <summary>The most area samples or VPLs per point an option accepts.</summary>
    public const int MaxSamples = 4096;

    private readonly Argument<FileInfo?> _scene = new("scene")
    {
        Description = $"Scene file (see docs/scenes.md). Default: the Qornell box with {DefaultQornellPrimitives} primitives, built in.",
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
        var scene = LoadScene(sceneFile);
        var kind = parse.GetValue(_engine.Engine);
        var engineName = EngineOptions.Name(kind);
        var stem = sceneFile is null ? $"qornell-{DefaultQornellPrimitives}" : Path.GetFileNameWithoutExtension(sceneFile.Name);
        var output = parse.GetValue(_output) ?? $"{stem}-{engineName}.png";
        var withReference = parse.GetValue(_reference);

        var (width, height) = ParseSize(parse.GetValue(_size)) is { Size: { } size } ? size : (scene.Width, scene.Height);
        var options = _render.Get(parse, width, height, parse.GetValue(_engine.Seed));
        var sampled = RenderDefaults.SamplesLight(scene, options);
        var referenceSamples = parse.GetValue(_referenceSamples);
        var withConverged = sampled && referenceSamples > 0;
        var converged = RenderDefaults.Converged(options, Math.Max(1, referenceSamples));
        string[] outputs = withReference
            ? [output, Sibling(output, "reference"), Sibling(output, "difference"), .. withConverged ? [Sibling(output, "converged")] : Array.Empty<string>()]
            : [output];
        ImageFiles.EnsureWritable(outputs, sceneFile is null ? [] : [sceneFile.FullName]);
        _json.EnsureWritable(parse, sceneFile is null ? outputs : [.. outputs, sceneFile.FullName]);
        using var bridges = _engine.StartBridges(parse);

        var noise = _engine.GetNoise(parse);
        EngineOptions.CheckNoise(kind, noise);
        var geometry = new SceneGeometry(scene);
        AnsiConsole.WriteLine($"{scene.Name}: N = {geometry.Count} primitives, {LightSummary(scene)}, {width}x{height} pixels, {scene.Grid}");
        if (sampled)
            AnsiConsole.WriteLine($"sampled light: {(scene.AreaLights.Count > 0 ? $"{options.AreaSamples} shadow rays per point and area light" : "no area lights")}, {(options.Vpl > 0 ? $"{options.Vpl} VPLs per point" : "no indirect light")}; "
                + (withConverged ? $"converged reference: {converged.AreaSamples} area samples{(options.Vpl > 0 ? $", {converged.Vpl} VPLs" : "")}" : "no converged reference"));
        AnsiConsole.WriteLine($"modelled per search: {geometry.IndexBits} index qubits + {SearchRegisters.For(geometry.Count).AuxiliaryQubits} auxiliaries, lookup table of {geometry.Count} rows x {scene.Grid.Bits} coordinate bits per axis");
        if (kind is EngineKind.FullState or EngineKind.Gate or EngineKind.Analytic) AnsiConsole.WriteLine($"noise model: {EngineOptions.NoiseDescription(kind, noise)}");
        OracleRegisters? gateRegisters = null;
        if (kind == EngineKind.Gate)
        {
            // Depth bits, and so the width, vary by ray: show the centre pixel's primary search.
            var centre = RayTable.Build(geometry, CameraRays.For(scene.Camera, width, height)[height / 2 * width + width / 2]);
            var registers = OracleRegisters.For(new OracleInput(centre, centre.FullRange));
            gateRegisters = registers;
            AnsiConsole.WriteLine($"gate-level oracle ({OracleConstruction.Default}), centre ray: {registers.RegisterQubits} register qubits ({registers.IndexQubits} index, {1 + registers.BoundRegisters} x {registers.CoordinateQubits} coordinate, {registers.DepthQubits} depth, {registers.FlagQubits} flags, 1 phase), {registers.PeakQubits} at peak with library auxiliaries");
        }

        var progress = new ConsoleProgress(engineName);
        var clock = Stopwatch.StartNew();
        RenderResult result;
        using (var search = EngineOptions.CreateHitSearch(kind, new SeededRandom(parse.GetValue(_engine.Seed)), parse.GetValue(_engine.Workers), _qsearch.Get(parse), parse.GetValue(_engine.MaxQubits), bridges, noise: noise))
        {
            try
            {
                result = SceneRenderer.Render(scene, search, options, progress);
            }
            catch (SimulatorLimitException e)
            {
                progress.Finish();
                throw new UserError($"{scene.Name}: {e.Message}");
            }
        }
        var renderTime = clock.Elapsed;
        clock.Restart();
        var referenceProgress = new ConsoleProgress("classical reference");
        using var classical = new ClassicalHitSearch();
        var reference = SceneRenderer.Render(scene, classical, RenderDefaults.Reference(options), referenceProgress);
        var referenceTime = clock.Elapsed;
        clock.Restart();
        RenderResult? convergedReference = null;
        if (withConverged)
        {
            var convergedProgress = new ConsoleProgress("converged reference");
            convergedReference = SceneRenderer.Render(scene, classical, converged, convergedProgress);
            convergedProgress.Finish();
        }
        var convergedTime = clock.Elapsed;
        progress.Finish();
        referenceProgress.Finish();

        var images = new List<(RgbImage, string)> { (result.Image, output) };
        if (withReference)
        {
            images.Add((reference.Image, outputs[1]));
            images.Add((DifferenceImage.Of(result.Image, reference.Image), outputs[2]));
            if (convergedReference is not null) images.Add((convergedReference.Image, outputs[3]));
        }
        ImageFiles.Write(images);

        var figures = new RenderFigures(scene.Name, geometry.Count, width, height, geometry.IndexBits, scene.Grid.Bits, gateRegisters, result.Passes, result.Total, reference.Total,
            ImageError.Between(result.Image, reference.Image), result.Budget,
            convergedReference is null ? null : referenceSamples,
            convergedReference is null ? null : ImageError.Between(result.Image, convergedReference.Image),
            convergedReference is null ? null : ImageError.Between(reference.Image, convergedReference.Image),
            renderTime, referenceTime, convergedReference is null ? null : convergedTime, images.Select(i => i.Item2).ToArray());
        AnsiConsole.WriteLine($"{engineName} ran on {EngineOptions.Where(kind, bridges, parse.GetValue(_engine.Workers))}");
        Print(noise.IsNoiseless ? engineName : $"{engineName} under {EngineOptions.NoiseDescription(kind, noise)}", figures, sampled, !noise.IsNoiseless);
        _json.Write(parse, figures, _engine);
        return 0;
    }

    private static void Print(string engineName, RenderFigures figures, bool sampled, bool noisy)
    {
        AnsiConsole.Write(MetricsTable(engineName, figures));
        var error = figures.Error;
        var sameSamples = sampled ? " with the same samples (search error alone)" : "";
        AnsiConsole.WriteLine($"error against the classical render{sameSamples}: NRMSE {error.Nrmse:P2} (RMS of 8-bit channel differences / reference range), #Dpix {error.DifferentPixels}, %Dpix {error.DifferentShare:P2}");
        // Against the accuracy budget: the expected share the searches allow (docs/accuracy.md) and the measured one.
        AnsiConsole.WriteLine($"wrong pixels: expected {figures.Budget.ExpectedWrongPixels:0.0} ({figures.Budget.ExpectedShare:P3}), measured {error.DifferentPixels} ({error.DifferentShare:P3}); budget {AccuracyBudget.Target:P1}");
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

    /// <summary>The scene file, or the built-in Qornell box with <see cref="DefaultQornellPrimitives"/> primitives when none is named.</summary>
    public static Scene LoadScene(FileInfo? file) => file is null
        ? SceneLoader.Parse(QornellBox.Build(DefaultQornellPrimitives).ToJson(), $"built-in qornell-{DefaultQornellPrimitives}")
        : SceneLoader.Load(file.FullName);

    /// <summary>out.png → out-reference.png.</summary>
    public static string Sibling(string output, string suffix)
    {
        var directory = Path.GetDirectoryName(output) ?? "";
        return Path.Combine(directory, $"{Path.GetFileNameWithoutExtension(output)}-{suffix}{Path.GetExtension(output)}");
    }

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
