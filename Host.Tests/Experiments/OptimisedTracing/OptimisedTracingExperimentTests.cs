using System.Globalization;
using QuantumRayTracing.Experiments;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Tests.Experiments;

/// <summary>`bench optimised-tracing` at 2x2: its tables hold the renders and rates they name, measured, not copied.</summary>
public sealed class OptimisedTracingExperimentTests
{
    private static Scene Load(string stem) => SceneLoader.Load(Path.Combine(RepositoryPaths.Scenes, stem + ".json"));

    private static readonly Lazy<Report> Report = new(() => OptimisedTracingExperiment.Run(new OptimisedTracingSettings(Load, 2, 7, 1), _ => { }));

    [Fact]
    public void Table5HoldsTheRenderOfItsRow()
    {
        var table = Report.Value.Table("table-5");
        Assert.Equal(8, table.Rows.Count);
        var row = Assert.Single(table.Rows, r => r[0] == "depth-complexity-64" && r[1] == "3");

        // The same render, seeded alike: the analytic engine gives the same image and counts for the same seed.
        var scene = Load("depth-complexity-64");
        var options = new RenderOptions(2, 2, Seed: 7) with { Iterations = 3, Neighbours = true };
        var m = RenderMeasurement.Run(scene, new EngineSetup(EngineKind.Analytic, new QSearchOptions(Rule: MSetRule.Round)), options, RenderMeasurement.Reference(scene, options));
        Assert.Equal(m.Result.Total.PerRayPaper.ToString("0.0", CultureInfo.InvariantCulture), table.Cell(row, "Int/Ray"));
        Assert.Equal(m.Error.DifferentPixels.ToString(CultureInfo.InvariantCulture), table.Cell(row, "#Dpix"));
        Assert.Equal(m.Result.Total.UpdatedPixels.ToString(CultureInfo.InvariantCulture), table.Cell(row, "#Cpix"));
    }

    [Fact]
    public void Table6MeasuresTheMissRateItComputes()
    {
        var table = Report.Value.Table("table-6");
        Assert.Equal(PaperNumbers.Table6.Count, table.Rows.Count);
        foreach (var row in table.Rows)
        {
            var n = int.Parse(row[0], CultureInfo.InvariantCulture);
            var exact = FalseNegativeRate.QSearchExact(new QSearchSchedule(n), FalseNegativeRate.Uniform(n, n));
            Assert.Equal(exact.ToString("0.000", CultureInfo.InvariantCulture), table.Cell(row, "exact, Alg. 1 (ceiling)"));
            // 20,000 searches at rates of at most 0.1 here: a standard deviation of at most sqrt(0.1 · 0.9 / 20,000) ≈ 0.0021.
            // 0.01 less the rounding of the measured cell to 3 decimals is 4.5 deviations: a false failure about once in 10^5 rows
            // (normal tail). Measuring the round rule's schedule instead would miss by 0.013 at N = 8 and 0.05 at N = 16.
            var measured = double.Parse(table.Cell(row, "measured, Alg. 1"), CultureInfo.InvariantCulture);
            Assert.InRange(measured, exact - 0.01, exact + 0.01);
        }
    }

    [Fact]
    public void Table7HasEveryPaperSceneAndTheBuiltInOne()
    {
        var table = Report.Value.Table("table-7");
        Assert.Equal([.. PaperNumbers.Optimised.Keys, "qornell-4096 (built in)"], table.Rows.Select(r => r[0]));
        Assert.All(table.Rows.SkipLast(1), r => Assert.Equal(PaperNumbers.Optimised[r[0]].IntPerRay.ToString("0.0", CultureInfo.InvariantCulture), table.Cell(r, "paper's table 7: Int/Ray")));
    }
}
