using System.Globalization;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// `bench render-results`: the paper's tables 2 and 3 on our renderer, the engines side by side, and the gate-level
/// oracle against the lookup form (docs/render-results.md).
/// </summary>
public static class RenderResultsExperiment
{
    public const string Title = "Rendering results";

    public static Report Run(RenderResultsSettings settings, Action<string> progress)
    {
        var (size, seed, workers) = (settings.Size, settings.Seed, settings.Workers);
        var paperRule = new QSearchOptions(Rule: MSetRule.Round);
        var ourRule = new QSearchOptions();
        var report = new Report(Title);
        report.Text($"""
            {size}x{size} pixels, seed {seed}, strict (depth, id) tie-breaking, Whitted shading, 2 DirectPass rounds. Error is against the classical render of the same
            scene and options: NRMSE = RMS of the 8-bit channel differences / the reference's value range; #Dpix = pixels whose 8-bit RGB differs.
            Int/Ray = (#Eval + #C_Int) / #Rays over primary, specular and shadow rays. *Paper count*: a Grover run with r iterations costs r, with
            QSearch's M_l = round(c^l) from l = 0 (the paper's table 6), the setting that reproduces the paper; *conservative*: r + 1, with
            Algorithm 1's M_l = ceil(c^l) from l = 1, our default (docs/conventions.md). Both on the analytic engine, which samples the exact outcome
            distribution of every Grover run (tests show it agrees with the full-state simulator).
            """);

        report.Heading("Scalability with the number of primitives (the paper's table 2)");
        var table2 = new TextTable("table-2", ["scene", "N", "#It", "classical Int/Ray", "Int/Ray, paper count", "paper's table 2", "ours / paper", "#Dpix", "Int/Ray, conservative", "#Dpix", "analytic / classical wall time"]);
        var stems = PaperNumbers.Scalability.Keys.ToArray();
        foreach (var (stem, k) in stems.Select((s, k) => (s, k)))
        {
            progress($"table 2: {stem} ({k + 1}/{stems.Length})");
            var scene = settings.Scene(stem);
            var options = RenderOptions.PaperPipeline(size, size, seed) with { Iterations = PaperNumbers.ScalabilityIterations(stem) };
            var reference = RenderMeasurement.Reference(scene, options);
            var paper = RenderMeasurement.Run(scene, new EngineSetup(EngineKind.Analytic, paperRule, workers), options, reference);
            var ours = RenderMeasurement.Run(scene, new EngineSetup(EngineKind.Analytic, ourRule, workers), options, reference);
            var published = PaperNumbers.Scalability[stem];
            table2.Row(stem, N(scene.Primitives.Count), N(options.Iterations), F(reference.Result.Total.PerRayConservative), F(paper.Result.Total.PerRayPaper), F(published),
                (paper.Result.Total.PerRayPaper / published).ToString("0.00", CultureInfo.InvariantCulture), N(paper.Error.DifferentPixels),
                F(ours.Result.Total.PerRayConservative), N(ours.Error.DifferentPixels), (ours.WallTime / reference.WallTime).ToString("0.0", CultureInfo.InvariantCulture) + "x");
        }
        report.Table(table2);

        report.Heading("Error against TracePass iterations (the paper's table 3)");
        var table3 = new TextTable("table-3", ["scene", "#It", "Int/Ray, paper count", "NRMSE", "#Dpix", "%Dpix", "paper: Int/Ray", "paper: NRMSE", "paper: #Dpix", "Int/Ray, conservative", "#Dpix, conservative"]);
        foreach (var (stem, rows) in PaperNumbers.Iterations)
        {
            var scene = settings.Scene(stem);
            foreach (var row in rows)
            {
                progress($"table 3: {stem}, {row.Iterations} iterations");
                var options = RenderOptions.PaperPipeline(size, size, seed) with { Iterations = row.Iterations };
                var reference = RenderMeasurement.Reference(scene, options);
                var paper = RenderMeasurement.Run(scene, new EngineSetup(EngineKind.Analytic, paperRule, workers), options, reference);
                var ours = RenderMeasurement.Run(scene, new EngineSetup(EngineKind.Analytic, ourRule, workers), options, reference);
                table3.Row(stem, N(row.Iterations), F(paper.Result.Total.PerRayPaper), P(paper.Error.Nrmse, "P1"), N(paper.Error.DifferentPixels), P(paper.Error.DifferentShare, "P1"),
                    F(row.IntPerRay), P(row.Nrmse, "P0"), N(row.DifferentPixels), F(ours.Result.Total.PerRayConservative), N(ours.Error.DifferentPixels));
            }
        }
        report.Table(table3);

        var engineSize = settings.EngineSize;
        CompareEngines(report, settings, "engines", $"Engines side by side (qornell-64, {engineSize}x{engineSize}, 4 passes, conservative count, default M rule)", null,
            settings.Scene("qornell-64"), RenderOptions.PaperPipeline(engineSize, engineSize, settings.Seed),
            [EngineKind.Classical, EngineKind.Randomized, EngineKind.Analytic, EngineKind.FullState], ourRule, progress);
        CompareEngines(report, settings, "gate-oracle", "The gate-level oracle against the lookup form (qornell-8, 8x8, 4 passes)",
            "The same searches with the oracle built from comparators (`gate`) and from the marked set (`fullstate`), both on the QDK simulator.",
            settings.Scene("qornell-8"), RenderOptions.PaperPipeline(8, 8, settings.Seed), [EngineKind.Gate, EngineKind.FullState], ourRule, progress);
        return report;
    }

    private static void CompareEngines(Report report, RenderResultsSettings settings, string name, string title, string? note, Scene scene, RenderOptions options,
        EngineKind[] kinds, QSearchOptions rule, Action<string> progress)
    {
        report.Heading(title);
        if (note is not null) report.Text(note);
        var table = new TextTable(name, ["engine", "#Rays", "Int/Ray", "NRMSE", "#Dpix", "wall time", "ms per ray", "wall time / classical"]);
        var classical = RenderMeasurement.Reference(scene, options);
        foreach (var kind in kinds)
        {
            progress($"{name}: {kind.ToString().ToLowerInvariant()}");
            var m = RenderMeasurement.Run(scene, new EngineSetup(kind, rule, settings.Workers, Pool: settings.Pool), options, classical);
            table.Row(kind.ToString().ToLowerInvariant(), N(m.Result.Total.Rays), F(m.Result.Total.PerRayConservative), P(m.Error.Nrmse, "P2"), N(m.Error.DifferentPixels),
                m.WallTime.TotalSeconds.ToString("0.00 s", CultureInfo.InvariantCulture), m.MillisecondsPerRay.ToString("0.000", CultureInfo.InvariantCulture),
                (m.WallTime / classical.WallTime).ToString("0.0", CultureInfo.InvariantCulture) + "x");
        }
        report.Table(table);
    }

    private static string F(double value) => value.ToString("0.0", CultureInfo.InvariantCulture);

    private static string N(long value) => value.ToString(CultureInfo.InvariantCulture);

    private static string P(double value, string format) => value.ToString(format, CultureInfo.InvariantCulture);
}
