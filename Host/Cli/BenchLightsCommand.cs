using System.CommandLine;
using System.Globalization;
using System.Text;
using QuantumRayTracing.Benchmarks;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Metrics;
using QuantumRayTracing.Output;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using Spectre.Console;

namespace QuantumRayTracing.Cli;

/// <summary>
/// `bench lights`: the paper's sec. 7 on our renderer — the Qornell box under an area light (32 shadow
/// rays per point) and the temple's VPL indirect light (4 VPLs per point): Int/Ray of each pipeline on
/// the quantum and classical engines, the error against the classical render with the same samples
/// (search error) and against a many-sample classical reference (search error plus Monte Carlo noise),
/// and small images of each beside its references. Written as Markdown and PNGs (docs/lights.md).
/// </summary>
public sealed class BenchLightsCommand : Command
{
    public const string CommandLine = "qrt bench lights";

    private readonly Option<DirectoryInfo> _scenes = new("--scenes")
    {
        Description = "Directory holding qornell-64-area.json and temple-32.json.",
        DefaultValueFactory = _ => new DirectoryInfo("Scenes"),
    };

    private readonly Option<int> _size = new("--size")
    {
        Description = "Square image size of the measured renders (the paper: 128).",
        DefaultValueFactory = _ => 128,
    };

    private readonly Option<int> _imageSize = new("--image-size")
    {
        Description = "Square size of the images written beside the report (rendered apart, same options).",
        DefaultValueFactory = _ => 64,
    };

    private readonly Option<int> _referenceSamples = new("--reference-samples")
    {
        Description = "Area samples and VPLs per point of the converged classical reference (the paper: 512).",
        DefaultValueFactory = _ => RenderDefaults.ReferenceSamples,
    };

    private readonly Option<ulong> _seed = new("--seed") { Description = "Seed of every render.", DefaultValueFactory = _ => 1UL };

    private readonly Option<FileInfo?> _output = new("--output", "-o")
    {
        Description = "Markdown report (e.g. docs/lights.md); the images go beside it as <name>-<case>-<render>.png. Replaces only files this command wrote. Default: the report is printed only, no images are written.",
    };

    public BenchLightsCommand() : base("lights", "Area light and VPL indirect light (the paper's sec. 7): Int/Ray and error of the quantum and classical pipelines, with images beside their classical references.")
    {
        Options.Add(_scenes);
        Options.Add(_size);
        Options.Add(_imageSize);
        Options.Add(_referenceSamples);
        Options.Add(_seed);
        Options.Add(_output);
        _size.Between(1, 1024);
        _imageSize.Between(1, 1024);
        _referenceSamples.Between(1, RenderCommand.MaxSamples);
        SetAction(Execute);
    }

    /// <summary>One of the paper's two sec. 7 experiments.</summary>
    private sealed record Case(string Key, string Stem, string Title, string Samples, RenderOptions Options, (double Quantum, double Classical) Paper, string[] SampledPasses);

    /// <summary>A pipeline measured on one engine.</summary>
    private sealed record Row(string Name, EngineKind Engine, RenderOptions Options, QSearchOptions QSearch, bool PaperCount);

    private int Execute(ParseResult parse)
    {
        var output = parse.GetValue(_output);
        var report = new GeneratedReport(output?.FullName, GeneratedReport.MarkdownMarker(CommandLine));
        report.EnsureWritable();
        var size = parse.GetValue(_size);
        var imageSize = parse.GetValue(_imageSize);
        var seed = parse.GetValue(_seed);
        var referenceSamples = parse.GetValue(_referenceSamples);
        var directory = parse.GetValue(_scenes)!;

        var plain = new RenderOptions(size, size, Seed: seed);
        var cases = new[]
        {
            new Case("area", "qornell-64-area", "Area light: Qornell box 64 under a ceiling light", $"{RenderDefaults.AreaSamples} shadow rays per point",
                plain with { AreaSamples = RenderDefaults.AreaSamples }, PaperNumbers.AreaLight, [AreaLightPass.Name]),
            new Case("indirect", "temple-32", "Indirect light: the temple lit through its ceiling", "4 VPLs per point",
                plain with { Vpl = 4 }, PaperNumbers.IndirectLight, [IndirectPass.TraceName, IndirectPass.ShadowName]),
        };
        var renders = new[] { "quantum", "classical", "reference" };
        var imagePaths = output is null ? [] : cases.SelectMany(c => renders.Select(r => ImagePath(output.FullName, c.Key, r))).ToArray();
        ImageFiles.EnsureWritable(imagePaths, []);
        var scenes = cases.ToDictionary(c => c.Key, c => SceneLoader.Load(Path.Combine(directory.FullName, c.Stem + ".json")));

        var text = new StringBuilder();
        text.AppendLine("# Area lights and indirect light (the paper's sec. 7)");
        text.AppendLine();
        text.AppendLine($"{size}x{size} pixels, seed {seed}, analytic engine (exact outcome distributions) for the quantum rows. Classical Monte Carlo samples the light;");
        text.AppendLine("the searches decide visibility. Two errors per render (NRMSE = RMS of 8-bit differences / reference range, #Dpix = pixels whose 8-bit");
        text.AppendLine("RGB differs): against the classical render with **the same samples** (same seed, so the same sample positions: what the searches get");
        text.AppendLine($"wrong) and against the **converged** classical reference with {referenceSamples} area samples or VPLs per point (that plus Monte Carlo noise).");
        text.AppendLine("*Conservative* counts r + 1 queries per Grover run, the *paper* count r with the M sets of its table 6 (docs/conventions.md).");
        text.AppendLine();

        var images = new List<(RgbImage, string)>();
        AnsiConsole.Progress().AutoClear(true).Start(progress =>
        {
            var task = progress.AddTask("renders", maxValue: cases.Length * 7);
            // A small render first on each engine, so the first measured row does not pay for JIT compilation.
            foreach (var row in Rows(cases[0].Options with { Width = 8, Height = 8 }))
                RenderMeasurement.Run(scenes[cases[0].Key], row.Engine, row.Options, row.QSearch, seed, 1, null);
            foreach (var c in cases)
            {
                var scene = scenes[c.Key];
                var rows = Rows(c.Options);
                var sameSamples = RenderMeasurement.Reference(scene, c.Options);
                task.Increment(1);
                var converged = RenderMeasurement.Run(scene, EngineKind.Classical, RenderDefaults.Converged(c.Options, referenceSamples), new QSearchOptions(), seed, 1, null);
                task.Increment(1);
                text.AppendLine($"## {c.Title} ({c.Samples}; paper: {F(c.Paper.Quantum)} Int/Ray against {F(c.Paper.Classical)} classically)");
                text.AppendLine();
                text.AppendLine($"| pipeline | engine | Int/Ray, conservative | Int/Ray, paper count | {string.Join(" | ", c.SampledPasses.Select(p => $"`{p}` pass Int/Ray"))} | NRMSE, same samples | #Dpix, same samples | NRMSE, converged | #Dpix, converged | wall time |");
                text.AppendLine($"|---|---|---|---|{string.Concat(c.SampledPasses.Select(_ => "---|"))}---|---|---|---|---|");
                RenderMeasurement? ours = null;
                foreach (var row in rows)
                {
                    var m = RenderMeasurement.Run(scene, row.Engine, row.Options, row.QSearch, seed, 1, sameSamples);
                    ours ??= m;
                    var toConverged = ImageError.Between(m.Result.Image, converged.Result.Image);
                    var passes = c.SampledPasses.Select(name => m.Result.Passes.Single(p => p.Name == name))
                        .Select(p => F(row.PaperCount ? p.PerRayPaper : p.PerRayConservative));
                    text.AppendLine($"| {row.Name} | {EngineOptions.Name(row.Engine)} | {F(m.Result.Total.PerRayConservative)} | {F(m.Result.Total.PerRayPaper)} | {string.Join(" | ", passes)} | {m.Error.Nrmse:P2} | {m.Error.DifferentPixels} | {toConverged.Nrmse:P2} | {toConverged.DifferentPixels} | {m.WallTime.TotalSeconds:0.0} s |");
                    task.Increment(1);
                }
                text.AppendLine($"| converged reference, {referenceSamples} samples | classical | {F(converged.Result.Total.PerRayConservative)} | {F(converged.Result.Total.PerRayPaper)} | {string.Join(" | ", c.SampledPasses.Select(_ => ""))} | | | 0.00 % | 0 | {converged.WallTime.TotalSeconds:0.0} s |");
                text.AppendLine();
                text.AppendLine(PassTable(ours!));

                // Images at a small size: our default pipeline, the classical render with its samples, the converged reference.
                if (output is null) continue;
                var small = c.Options with { Width = imageSize, Height = imageSize };
                var quantum = RenderMeasurement.Run(scene, EngineKind.Analytic, Default(small), new QSearchOptions(), seed, 1, null);
                var classical = RenderMeasurement.Reference(scene, small);
                var reference = RenderMeasurement.Run(scene, EngineKind.Classical, RenderDefaults.Converged(small, referenceSamples), new QSearchOptions(), seed, 1, null);
                var paths = renders.Select(r => ImagePath(output.FullName, c.Key, r)).ToArray();
                images.AddRange([(quantum.Result.Image, paths[0]), (classical.Result.Image, paths[1]), (reference.Result.Image, paths[2])]);
                text.AppendLine($"{imageSize}x{imageSize}: our default quantum pipeline, the classical render with the same samples, the converged classical reference ({referenceSamples} samples);");
                text.AppendLine($"NRMSE against the converged reference {ImageError.Between(quantum.Result.Image, reference.Result.Image).Nrmse:P2} (quantum) and {ImageError.Between(classical.Result.Image, reference.Result.Image).Nrmse:P2} (classical, same samples).");
                text.AppendLine();
                text.AppendLine("| quantum, default pipeline | classical, same samples | classical, converged |");
                text.AppendLine("|---|---|---|");
                text.AppendLine($"| {string.Join(" | ", paths.Select(p => $"![{Path.GetFileNameWithoutExtension(p)}]({Path.GetFileName(p)})"))} |");
                text.AppendLine();
            }
        });
        text.AppendLine("Rows: *default* is `render` with no options but the sample count (NeighOpt, occluder gathering with a layout channel per light and sample");
        text.AppendLine($"or VPL index, exact termination, a lattice of {RenderDefaults.LatticeLevelsFor(size, size)} levels with cheap confirmations where neighbours agree; the VPL shadow pass runs without");
        text.AppendLine("termination, see docs/rendering.md); *paper's configuration* is NeighOpt on primary and specular rays with the paper's termination and up to 8");
        text.AppendLine("rounds, in the paper's count (as in optimised-tracing.md's table 7); *no optimisation* is 4 TracePass and 2 DirectPass rounds. The classical");
        text.AppendLine("engine through our default pipeline shows what the pipeline alone saves (docs/conventions.md); plain classical costs N per ray. The paper's");
        text.AppendLine("configuration ends shadow rays by the termination criterion too but gathers no occluders, so a shadow ray whose one search missed its");
        text.AppendLine("occluder usually stays lit: that is where its wrong pixels come from (with occluder gathering its area-light error falls to the default's).");
        text.AppendLine();
        text.AppendLine($"Machine: {MachineDescription.Describe(null, null)}.");
        text.AppendLine($"Command: `dotnet run --project Host -c Release -- {string.Join(' ', Environment.GetCommandLineArgs().Skip(1))}`.");
        var body = text.ToString();
        Console.WriteLine(body);
        if (output is null) return 0;
        ImageFiles.Write(images);
        report.Write(body);
        return 0;
    }

    // Our default pipeline: what `render` uses with no options.
    private static RenderOptions Default(RenderOptions options) => RenderDefaults.Options(options.Width, options.Height, options.Seed) with
    {
        AreaSamples = options.AreaSamples, Vpl = options.Vpl,
    };

    private static Row[] Rows(RenderOptions options)
    {
        var ours = new QSearchOptions();
        var paper = new QSearchOptions(Rule: MSetRule.Round);
        return
        [
            new("default", EngineKind.Analytic, Default(options), ours, false),
            new("paper's configuration", EngineKind.Analytic, options with { Iterations = 8, Neighbours = true, Stop = StopMode.Paper }, paper, true),
            new("no optimisation", EngineKind.Analytic, options, ours, false),
            new("default", EngineKind.Classical, Default(options), ours, false),
            new("plain", EngineKind.Classical, options, ours, false),
        ];
    }

    // Int/Ray of every pass of the default quantum pipeline (the first row), conservative count.
    private static string PassTable(RenderMeasurement m)
    {
        var passes = m.Result.Passes.Where(p => p.Rays > 0).Append(m.Result.Total).ToArray();
        var text = new StringBuilder();
        text.AppendLine("Default quantum pipeline, per pass (conservative count):");
        text.AppendLine();
        text.AppendLine($"| | {string.Join(" | ", passes.Select(p => p.Name))} |");
        text.AppendLine($"|---|{string.Concat(passes.Select(_ => "---|"))}");
        text.AppendLine($"| #Rays | {string.Join(" | ", passes.Select(p => p.Rays.ToString("N0", CultureInfo.InvariantCulture)))} |");
        text.AppendLine($"| Int/Ray | {string.Join(" | ", passes.Select(p => F(p.PerRayConservative)))} |");
        text.AppendLine($"| #Cpix | {string.Join(" | ", passes.Select(p => p.UpdatedPixels.ToString("N0", CultureInfo.InvariantCulture)))} |");
        return text.ToString();
    }

    private static string ImagePath(string report, string key, string render) =>
        Path.Combine(Path.GetDirectoryName(report)!, $"{Path.GetFileNameWithoutExtension(report)}-{key}-{render}.png");

    private static string F(double value) => value.ToString("0.0", CultureInfo.InvariantCulture);
}
