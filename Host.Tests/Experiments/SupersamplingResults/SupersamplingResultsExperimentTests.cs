using System.Globalization;
using QuantumRayTracing.Experiments;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Tests.Experiments;

/// <summary>`bench supersampling-results`'s report holds the measured errors where its headers say, and its data hold every point.</summary>
public sealed class SupersamplingResultsExperimentTests
{
    // Two means per point: every estimator still averages over trials, and the cells are checked against the same measurement.
    private const int Trials = 2;
    private const ulong Seed = 4;

    private static readonly Report Report = SupersamplingResultsExperiment.Run(new SupersamplingResultsSettings(Trials, Seed), _ => { });

    // The same seed gives the same points, so each cell can be checked against the measurement itself.
    private static readonly List<SupersamplingBenchmark.Point> Points = SupersamplingBenchmark.ErrorVersusQueries(Trials, Seed);

    private static string E(double value) => value.ToString("0.00000", CultureInfo.InvariantCulture);

    [Fact]
    public void ErrorTableShowsEachMethodsErrorAndTheBestQCoin()
    {
        var table = Report.Table("error-vs-queries");
        Assert.Equal(SupersamplingBenchmark.QueryLevels.Select(q => q.ToString(CultureInfo.InvariantCulture)), table.Rows.Select(r => r[0]));
        foreach (var q in SupersamplingBenchmark.QueryLevels)
        {
            var key = q.ToString(CultureInfo.InvariantCulture);
            Assert.Equal(E(Points.Single(p => p.Method == "mc" && p.Queries == q).MeanError), table.Cell(table.Rows.Single(r => r[0] == key), "MC"));
            var qcoin = Points.Where(p => p.Method == "qcoin" && p.Queries == q).ToList();
            var best = qcoin.MinBy(p => p.MeanError)!;
            Assert.Equal($"{E(best.MeanError)} ({best.Parameter})", table.Cell(table.Rows.Single(r => r[0] == key), "QCoin best (k)"));
            // The best is no worse than any fixed k shown.
            Assert.All(qcoin, p => Assert.True(best.MeanError <= p.MeanError));
        }
    }

    [Fact]
    public void DataHoldEveryPointAndThePlotsOneSeriesPerCurve()
    {
        var data = Report.DataTable();
        Assert.Equal(["method", "parameter", "queries", "mean_abs_error"], data.Header);
        Assert.Equal(Points.Count, data.Rows.Count);
        Assert.Equal(Points.Select(p => p.MeanError.ToString("G6", CultureInfo.InvariantCulture)), data.Rows.Select(r => r[3]));
        // The names the command checks before the work are the ones the report writes.
        Assert.Equal(SupersamplingResultsExperiment.Pictures, Report.PlotBlocks().Select(p => p.Name));
        Assert.Equal(SupersamplingResultsExperiment.DataTables, Report.Blocks.OfType<ReportData>().Select(d => d.Table.Name ?? ""));
        Assert.Equal(5, Report.PlotBlocks()[0].Spec.Series.Count);
        Assert.Equal(6, Report.PlotBlocks()[1].Spec.Series.Count);
    }

    [Fact]
    public void LookupTableRowsAreExactSums()
    {
        // With hit counts equally likely, QSS's exact table at N = 16, t = 4 beats Monte Carlo with 15 samples (thesis 004: 0.9 against 1.2 hits).
        var row = Report.Table("qss-lookup-table").Rows.Single(r => r[0] == "16" && r[1] == "4");
        var (qss, mc) = (double.Parse(row[2], CultureInfo.InvariantCulture), double.Parse(row[5], CultureInfo.InvariantCulture));
        Assert.InRange(qss, 0.5, 1.1);
        Assert.InRange(mc, 1.0, 1.4);
        Assert.True(qss < mc);
    }
}
