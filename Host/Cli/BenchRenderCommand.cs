using System.CommandLine;
using System.Globalization;
using System.Text;
using QuantumRayTracing.Benchmarks;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Output;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using Spectre.Console;

namespace QuantumRayTracing.Cli;

/// <summary>
/// `bench render`: the paper's tables 2 and 3 on our renderer, and the engines side by side, written
/// as Markdown (docs/rendering-results.md).
/// </summary>
public sealed class BenchRenderCommand : Command
{
    public const string CommandLine = "qrt bench render";

    private readonly Option<int> _size = new("--size")
    {
        Description = "Square image size of the table 2 and 3 renders (the paper: 128).",
        DefaultValueFactory = _ => 128,
    };

    private readonly Option<int> _engineSize = new("--engine-size")
    {
        Description = "Square image size of the engine comparison (the full-state simulator is slow).",
        DefaultValueFactory = _ => 32,
    };

    private readonly BenchReportOptions _report = new(CommandLine, "docs/rendering-results.md");

    public BenchRenderCommand() : base("render", "Renders for the paper's tables 2 and 3 (Int/Ray, NRMSE, #Dpix), an engine comparison (wall time per ray) and the gate-level oracle against the lookup form.")
    {
        Options.Add(_size);
        Options.Add(_engineSize);
        _report.AddTo(this);
        _size.Between(1, 1024);
        _engineSize.Between(1, 1024);
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var report = _report.Report(parse);
        Scene Load(string stem) => _report.Load(parse, stem);
        var size = parse.GetValue(_size);
        var seed = parse.GetValue(_report.Seed);
        var workers = parse.GetValue(_report.Workers);
        var paperRule = new QSearchOptions(Rule: MSetRule.Round);
        var ourRule = new QSearchOptions();
        var text = new StringBuilder();
        text.AppendLine("# Rendering results");
        text.AppendLine();
        text.AppendLine($"{size}x{size} pixels, seed {seed}, strict (depth, id) tie-breaking, Whitted shading, 2 DirectPass rounds. Error is against the classical render of the same");
        text.AppendLine("scene and options: NRMSE = RMS of the 8-bit channel differences / the reference's value range; #Dpix = pixels whose 8-bit RGB differs.");
        text.AppendLine("Int/Ray = (#Eval + #C_Int) / #Rays over primary, specular and shadow rays. *Paper count*: a Grover run with r iterations costs r, with");
        text.AppendLine("QSearch's M_l = round(c^l) from l = 0 (the paper's table 6), the setting that reproduces the paper; *conservative*: r + 1, with");
        text.AppendLine("Algorithm 1's M_l = ceil(c^l) from l = 1, our default (docs/conventions.md). Both on the analytic engine, which samples the exact outcome");
        text.AppendLine("distribution of every Grover run (tests show it agrees with the full-state simulator).");
        text.AppendLine();

        AnsiConsole.Progress().AutoClear(true).Start(progress =>
        {
            var stems = PaperNumbers.Scalability.Keys.ToArray();
            var task = progress.AddTask("table 2", maxValue: stems.Length);
            text.AppendLine("## Scalability with the number of primitives (the paper's table 2)");
            text.AppendLine();
            text.AppendLine("| scene | N | #It | classical Int/Ray | Int/Ray, paper count | paper's table 2 | ours / paper | #Dpix | Int/Ray, conservative | #Dpix | analytic / classical wall time |");
            text.AppendLine("|---|---|---|---|---|---|---|---|---|---|---|");
            foreach (var stem in stems)
            {
                var scene = Load(stem);
                var options = new RenderOptions(size, size, PaperNumbers.ScalabilityIterations(stem));
                var reference = RenderMeasurement.Reference(scene, options);
                var paper = RenderMeasurement.Run(scene, EngineKind.Analytic, options, paperRule, seed, workers, reference);
                var ours = RenderMeasurement.Run(scene, EngineKind.Analytic, options, ourRule, seed, workers, reference);
                var published = PaperNumbers.Scalability[stem];
                text.AppendLine($"| {stem} | {scene.Rectangles.Count} | {options.Iterations} | {F(reference.Result.Total.PerRayConservative)} | {F(paper.Result.Total.PerRayPaper)} | {F(published)} | {paper.Result.Total.PerRayPaper / published:0.00} | {paper.Error.DifferentPixels} | {F(ours.Result.Total.PerRayConservative)} | {ours.Error.DifferentPixels} | {ours.WallTime / reference.WallTime:0.0}x |");
                task.Increment(1);
            }
            text.AppendLine();

            text.AppendLine("## Error against TracePass iterations (the paper's table 3)");
            text.AppendLine();
            text.AppendLine("| scene | #It | Int/Ray, paper count | NRMSE | #Dpix | %Dpix | paper: Int/Ray | paper: NRMSE | paper: #Dpix | Int/Ray, conservative | #Dpix, conservative |");
            text.AppendLine("|---|---|---|---|---|---|---|---|---|---|---|");
            foreach (var (stem, rows) in PaperNumbers.Iterations)
            {
                var scene = Load(stem);
                var rowTask = progress.AddTask($"table 3: {stem}", maxValue: rows.Length);
                foreach (var row in rows)
                {
                    var options = new RenderOptions(size, size, row.Iterations);
                    var reference = RenderMeasurement.Reference(scene, options);
                    var paper = RenderMeasurement.Run(scene, EngineKind.Analytic, options, paperRule, seed, workers, reference);
                    var ours = RenderMeasurement.Run(scene, EngineKind.Analytic, options, ourRule, seed, workers, reference);
                    text.AppendLine($"| {stem} | {row.Iterations} | {F(paper.Result.Total.PerRayPaper)} | {paper.Error.Nrmse:P1} | {paper.Error.DifferentPixels} | {paper.Error.DifferentShare:P1} | {F(row.IntPerRay)} | {row.Nrmse:P0} | {row.DifferentPixels} | {F(ours.Result.Total.PerRayConservative)} | {ours.Error.DifferentPixels} |");
                    rowTask.Increment(1);
                }
            }
            text.AppendLine();

            void CompareEngines(string title, string note, Scene scene, RenderOptions options, EngineKind[] kinds)
            {
                text.AppendLine(title);
                text.AppendLine();
                if (note.Length > 0) text.AppendLine(note).AppendLine();
                text.AppendLine("| engine | #Rays | Int/Ray | NRMSE | #Dpix | wall time | ms per ray | wall time / classical |");
                text.AppendLine("|---|---|---|---|---|---|---|---|");
                var classical = RenderMeasurement.Reference(scene, options);
                var task = progress.AddTask(title.TrimStart('#', ' '), maxValue: kinds.Length);
                foreach (var kind in kinds)
                {
                    var m = RenderMeasurement.Run(scene, kind, options, ourRule, seed, workers, classical);
                    text.AppendLine($"| {EngineOptions.Name(kind)} | {m.Result.Total.Rays} | {F(m.Result.Total.PerRayConservative)} | {m.Error.Nrmse:P2} | {m.Error.DifferentPixels} | {m.WallTime.TotalSeconds:0.00} s | {m.MillisecondsPerRay:0.000} | {m.WallTime / classical.WallTime:0.0}x |");
                    task.Increment(1);
                }
                text.AppendLine();
            }

            var engineSize = parse.GetValue(_engineSize);
            CompareEngines($"## Engines side by side (qornell-64, {engineSize}x{engineSize}, 4 passes, conservative count, default M rule)", "",
                Load("qornell-64"), new RenderOptions(engineSize, engineSize),
                [EngineKind.Classical, EngineKind.Randomized, EngineKind.Analytic, EngineKind.FullState]);
            CompareEngines("## The gate-level oracle against the lookup form (qornell-8, 8x8, 4 passes)",
                "The same searches with the oracle built from comparators (`gate`) and from the marked set (`fullstate`), both on the QDK simulator.",
                Load("qornell-8"), new RenderOptions(8, 8), [EngineKind.Gate, EngineKind.FullState]);
        });
        BenchReportOptions.Publish(report, text);
        return 0;
    }

    private static string F(double value) => value.ToString("0.0", CultureInfo.InvariantCulture);
}
