using System.Globalization;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Output;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// `bench speed-vs-error`: speed against error for every configuration of every engine on one scene — Int/Ray and
/// wall time against NRMSE and #Dpix, Pareto fronts marked — as a table and two plots (docs/speed-vs-error.md).
/// </summary>
public static class SpeedVsErrorExperiment
{
    public const string Title = "Speed against error";

    /// <summary>Every engine but `gate`, too slow for whole images.</summary>
    public static readonly EngineKind[] Engines = [EngineKind.Classical, EngineKind.Randomized, EngineKind.Analytic, EngineKind.FullState];

    /// <summary>The plots beside the report: &lt;report&gt;-intray.png and &lt;report&gt;-walltime.png.</summary>
    public static readonly string[] PlotNames = ["intray", "walltime"];

    /// <summary>One configuration on one engine: its cost (conservative Int/Ray, wall time) and error.</summary>
    public sealed record Point(string Engine, string Configuration, double IntPerRay, double Seconds, double Nrmse, int DifferentPixels);

    /// <summary>The pipeline configurations measured: plain rounds, neighbours, termination and the lattice with several cheap-confirmation misses.</summary>
    public static IReadOnlyList<(string Name, RenderOptions Options)> Configurations(int size, ulong seed)
    {
        var plain = RenderOptions.PaperPipeline(size, size, seed);
        var configurations = new List<(string Name, RenderOptions Options)>();
        for (var it = 1; it <= 5; it++) configurations.Add(($"base, #IT {it}", plain with { Iterations = it }));
        for (var it = 1; it <= 3; it++) configurations.Add(($"neighbours, #IT {it}", plain with { Iterations = it, Neighbours = true }));
        configurations.Add(("neighbours + stop", plain with { Iterations = 8, Neighbours = true, ShadowNeighbours = true, Stop = StopMode.Exact }));
        foreach (var (levels, miss) in new[] { (2, 0.025), (4, 0.025), (4, 0.2), (4, 0.4), (4, 0.6) })
            configurations.Add(($"lattice {levels}, agreed miss {miss}", plain with
            {
                Neighbours = true, ShadowNeighbours = true, Stop = StopMode.Exact, LatticeLevels = levels, AgreedMiss = miss,
            }));
        return configurations;
    }

    public static Report Run(SpeedVsErrorSettings settings, Action<string> progress)
    {
        var (scene, size, seed) = (settings.Scene, settings.Size, settings.Seed);
        var configurations = Configurations(size, seed);
        var points = new List<Point>();
        foreach (var kind in Engines)
            foreach (var (name, options) in configurations)
            {
                progress($"{EngineFactory.Name(kind)}: {name} ({points.Count + 1}/{Engines.Length * configurations.Count})");
                var reference = RenderMeasurement.Reference(scene, options);
                var m = RenderMeasurement.Run(scene, new EngineSetup(kind, new QSearchOptions(), settings.Workers, Pool: settings.Pool), options, reference);
                points.Add(new(EngineFactory.Name(kind), name, m.Result.Total.PerRayConservative, m.WallTime.TotalSeconds, m.Error.Nrmse, m.Error.DifferentPixels));
            }

        var intFront = ParetoFront.Of([.. points.Select(p => (p.IntPerRay, p.Nrmse))]).ToHashSet();
        var timeFront = ParetoFront.Of([.. points.Select(p => (p.Seconds, p.Nrmse))]).ToHashSet();
        var report = new Report(Title);
        report.Text($"""
            {scene.Name}, {size}x{size}, seed {seed}: every configuration on every engine but `gate` (too slow for whole images). Int/Ray in the
            conservative count (docs/conventions.md); NRMSE and #Dpix against the classical render (strict ties, no tricks). ★ marks the Pareto front of
            Int/Ray against NRMSE, ☆ that of wall time against NRMSE (lower is better on both axes).
            """);
        var table = new TextTable("points", ["engine", "configuration", "Int/Ray", "wall time", "NRMSE", "#Dpix", "front"]);
        for (var i = 0; i < points.Count; i++)
        {
            var p = points[i];
            table.Row(p.Engine, p.Configuration, p.IntPerRay.ToString("0.0", CultureInfo.InvariantCulture), p.Seconds.ToString("0.000 s", CultureInfo.InvariantCulture),
                p.Nrmse.ToString("P2", CultureInfo.InvariantCulture), p.DifferentPixels.ToString(CultureInfo.InvariantCulture),
                (intFront.Contains(i) ? "★" : "") + (timeFront.Contains(i) ? "☆" : ""));
        }
        report.Table(table);
        report.Plot(PlotNames[0], Plot("Int/Ray against NRMSE", "Int/Ray (conservative)", AxisScale.Linear, points, p => p.IntPerRay, intFront), "Int/Ray against error");
        report.Plot(PlotNames[1], Plot("Wall time against NRMSE", "wall time (s)", AxisScale.Log10, points, p => p.Seconds, timeFront), "Wall time against error");
        return report;
    }

    // One scatter series per engine, and the Pareto front as a line; NRMSE on a log axis (+0.01% so exact renders show).
    private static PlotSpec Plot(string title, string xLabel, AxisScale xScale, List<Point> points, Func<Point, double> x, HashSet<int> front)
    {
        const double floor = 1e-4;
        var series = points.GroupBy(p => p.Engine)
            .Select(g => new PlotSeries(g.Key, [.. g.Select(p => (x(p), p.Nrmse + floor))], Lines: false))
            .ToList();
        series.Add(new PlotSeries("Pareto front", [.. front.Select(i => points[i]).OrderBy(x).Select(p => (x(p), p.Nrmse + floor))], Markers: false));
        return new PlotSpec(title, xLabel, "NRMSE + 0.0001", xScale, AxisScale.Log10, series);
    }
}
