using System.Globalization;
using QuantumRayTracing.Experiments;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Tests.Experiments;

/// <summary>`bench supersampling-images`' report at a tiny size: its tables agree with the runs in its data, and the confidence bins count every pixel once.</summary>
public sealed class SupersamplingImagesExperimentTests
{
    private static readonly Report Report = SupersamplingImagesExperiment.Run(new SupersamplingImagesSettings(1, [4]), _ => { });

    [Fact]
    public void DataHoldOneRunPerConfigurationAndSeed()
    {
        var runs = Report.DataTable();
        // Fig. 1's six estimators, then MC and QSS on the colour and the black-and-white 4x4 output.
        Assert.Equal(6 + 4, runs.Rows.Count);
        Assert.Equal(["MC", "QSS planes t=4 P=1"], runs.Rows.Where(r => r[0] == "qornell black-and-white").Select(r => r[3]));
        Assert.All(runs.Rows, r => Assert.Equal("1", r[5]));
    }

    [Fact]
    public void TablesShowTheRunsErrors()
    {
        var runs = Report.DataTable();
        var figure = Report.Table("fig-1");
        foreach (var run in runs.Rows.Where(r => r[2] == "64"))
        {
            // The data keep 6 significant digits, the tables 3 or 1 decimals: equal within the table's rounding.
            Assert.Equal(Number(run[6]), Number(figure.Cell(figure.Rows.Single(r => r[0] == run[3]), "mean abs error (levels)")), 0.0005 + 1e-9);
            Assert.Equal(100 * Number(run[9]), Number(figure.Cell(figure.Rows.Single(r => r[0] == run[3]), "exact pixels").TrimEnd('%')), 0.05 + 1e-9);
        }
        var tables = Report.Table("tables");
        var mc = runs.Rows.Single(r => r[0] == "qornell" && r[2] == "16" && r[3] == "MC");
        var cell = tables.Cell(tables.Rows.Single(r => r[0] == "qornell"), "exact MC");
        Assert.Equal(100 * Number(mc[9]), Number(cell.TrimEnd('%')), 0.05 + 1e-9);
    }

    private static double Number(string text) => double.Parse(text, CultureInfo.InvariantCulture);

    [Fact]
    public void ConfidenceBinsCountEveryPixelOnce()
    {
        var correlation = Report.Table("confidence-correlation");
        var bins = Report.DataTable("confidence");
        foreach (var input in correlation.Rows)
        {
            var pixels = bins.Rows.Where(b => b[0] == input[0]).Sum(b => int.Parse(b[3], CultureInfo.InvariantCulture));
            Assert.Equal(int.Parse(input[1], CultureInfo.InvariantCulture), pixels);
        }
        // 4x4 outputs for the thesis's inputs, 64x64 for fig. 1's.
        Assert.Equal(["16", "16", "4096"], correlation.Rows.Select(r => r[1]));
        // The names the command checks before the work are the ones the report writes.
        Assert.Equal(SupersamplingImagesExperiment.Pictures.Order(), Report.Blocks.Select(b => b switch { ReportPlot p => p.Name, ReportImage i => i.Name, _ => null }).OfType<string>().Order());
        Assert.Equal(SupersamplingImagesExperiment.DataTables.Order(), Report.Blocks.OfType<ReportData>().Select(d => d.Table.Name ?? "").Order());
    }
}
