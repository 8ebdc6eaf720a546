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
/// `bench pareto`: speed against error for every configuration of every engine on one scene —
/// Int/Ray and wall time against NRMSE and #Dpix, Pareto fronts marked — as a Markdown table and PNG plots.
/// </summary>
public sealed class BenchParetoCommand : Command
{
    public const string CommandLine = "qrt bench pareto";

    private readonly Option<FileInfo> _scene = new("--scene")
    {
        Description = "Scene to render.",
        DefaultValueFactory = _ => new FileInfo(Path.Combine("Scenes", "qornell-64.json")),
    };

    private readonly Option<int> _size = new("--size")
    {
        Description = "Square image size (the full-state engine renders every configuration too).",
        DefaultValueFactory = _ => 32,
    };

    private readonly BenchReportOptions _report = new(CommandLine, "docs/speed-vs-error.md; the plots go beside it as <name>-intray.png and <name>-walltime.png");

    public BenchParetoCommand() : base("pareto", "Speed against error for every configuration of every engine (classical, randomized, analytic, fullstate), Pareto fronts marked, with PNG plots.")
    {
        Options.Add(_scene);
        Options.Add(_size);
        _report.AddTo(this, scenes: false);
        _size.Between(1, 1024);
        SetAction(Execute);
    }

    internal sealed record Point(string Engine, string Configuration, double IntPerRay, double Seconds, double Nrmse, int DifferentPixels);

    private int Execute(ParseResult parse)
    {
        var output = parse.GetValue(_report.Output);
        var report = _report.Report(parse);
        var plotPaths = output is null ? [] : new[] { "intray", "walltime" }.Select(k => Path.ChangeExtension(RenderCommand.Sibling(output.FullName, k), ".png")).ToArray();
        ImageFiles.EnsureWritable(plotPaths, []);
        var sceneFile = parse.GetValue(_scene)!;
        var scene = SceneLoader.Load(sceneFile.FullName);
        var size = parse.GetValue(_size);
        var seed = parse.GetValue(_report.Seed);
        var plain = new RenderOptions(size, size, Seed: seed);
        var configurations = new List<(string Name, RenderOptions Options)>();
        for (var it = 1; it <= 5; it++) configurations.Add(($"base, #IT {it}", plain with { Iterations = it }));
        for (var it = 1; it <= 3; it++) configurations.Add(($"neighbours, #IT {it}", plain with { Iterations = it, Neighbours = true }));
        configurations.Add(("neighbours + stop", plain with { Iterations = 8, Neighbours = true, ShadowNeighbours = true, Stop = StopMode.Exact }));
        foreach (var (levels, miss) in new[] { (2, 0.025), (4, 0.025), (4, 0.2), (4, 0.4), (4, 0.6) })
            configurations.Add(($"lattice {levels}, agreed miss {miss}", plain with
            {
                Neighbours = true, ShadowNeighbours = true, Stop = StopMode.Exact, LatticeLevels = levels, AgreedMiss = miss,
            }));
        EngineKind[] engines = [EngineKind.Classical, EngineKind.Randomized, EngineKind.Analytic, EngineKind.FullState];

        var points = new List<Point>();
        AnsiConsole.Progress().AutoClear(true).Start(progress =>
        {
            var task = progress.AddTask("configurations", maxValue: engines.Length * configurations.Count);
            foreach (var kind in engines)
                foreach (var (name, options) in configurations)
                {
                    var reference = RenderMeasurement.Reference(scene, options);
                    var m = RenderMeasurement.Run(scene, kind, options, new QSearchOptions(), seed, parse.GetValue(_report.Workers), reference);
                    points.Add(new(EngineOptions.Name(kind), name, m.Result.Total.PerRayConservative, m.WallTime.TotalSeconds, m.Error.Nrmse, m.Error.DifferentPixels));
                    task.Increment(1);
                }
        });

        var intFront = ParetoFront.Of([.. points.Select(p => (p.IntPerRay, p.Nrmse))]).ToHashSet();
        var timeFront = ParetoFront.Of([.. points.Select(p => (p.Seconds, p.Nrmse))]).ToHashSet();
        var text = new StringBuilder();
        text.AppendLine("# Speed against error");
        text.AppendLine();
        text.AppendLine($"{scene.Name}, {size}x{size}, seed {seed}: every configuration on every engine but `gate` (too slow for whole images). Int/Ray in the");
        text.AppendLine("conservative count (docs/conventions.md); NRMSE and #Dpix against the classical render (strict ties, no tricks). ★ marks the Pareto front of");
        text.AppendLine("Int/Ray against NRMSE, ☆ that of wall time against NRMSE (lower is better on both axes).");
        text.AppendLine();
        text.AppendLine("| engine | configuration | Int/Ray | wall time | NRMSE | #Dpix | front |");
        text.AppendLine("|---|---|---|---|---|---|---|");
        for (var i = 0; i < points.Count; i++)
        {
            var p = points[i];
            text.AppendLine($"| {p.Engine} | {p.Configuration} | {p.IntPerRay.ToString("0.0", CultureInfo.InvariantCulture)} | {p.Seconds:0.000} s | {p.Nrmse:P2} | {p.DifferentPixels} | {(intFront.Contains(i) ? "★" : "")}{(timeFront.Contains(i) ? "☆" : "")} |");
        }
        if (output is not null)
        {
            text.AppendLine();
            text.AppendLine($"![Int/Ray against error]({Path.GetFileName(plotPaths[0])})");
            text.AppendLine();
            text.AppendLine($"![Wall time against error]({Path.GetFileName(plotPaths[1])})");
        }
        if (output is not null)
            ImageFiles.Write(
            [
                (Plot("Int/Ray against NRMSE", "Int/Ray (conservative)", AxisScale.Linear, points, p => p.IntPerRay, intFront), plotPaths[0]),
                (Plot("Wall time against NRMSE", "wall time (s)", AxisScale.Log10, points, p => p.Seconds, timeFront), plotPaths[1]),
            ]);
        BenchReportOptions.Publish(report, text);
        return 0;
    }

    // One scatter series per engine, and the Pareto front as a line; NRMSE on a log axis (+0.01% so exact renders show).
    internal static RgbImage Plot(string title, string xLabel, AxisScale xScale, List<Point> points, Func<Point, double> x, HashSet<int> front)
    {
        const double floor = 1e-4;
        var series = points.GroupBy(p => p.Engine)
            .Select(g => new PlotSeries(g.Key, [.. g.Select(p => (x(p), p.Nrmse + floor))], Lines: false))
            .ToList();
        series.Add(new PlotSeries("Pareto front", [.. front.Select(i => points[i]).OrderBy(x).Select(p => (x(p), p.Nrmse + floor))], Markers: false));
        return PlotImage.Render(new PlotSpec(title, xLabel, "NRMSE + 0.0001", xScale, AxisScale.Log10, series));
    }
}
