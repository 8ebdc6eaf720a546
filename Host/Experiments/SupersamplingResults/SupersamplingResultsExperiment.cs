using System.Globalization;
using QuantumRayTracing.Output;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;
using Point = QuantumRayTracing.Experiments.SupersamplingBenchmark.Point;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// `bench supersampling-results`: error against queries for Monte Carlo, QSS, QCoin and MLAE on the analytic engine (the QCoin
/// paper's figs. 7-8, with a CSV of every point and two log-log plots), and the QSS lookup table's accuracy
/// (docs/supersampling-results.md).
/// </summary>
public static class SupersamplingResultsExperiment
{
    public const string Title = "Supersampling results";

    /// <summary>The report's plots and data tables, by name, for checking their files before the work.</summary>
    public static readonly string[] Pictures = ["error-vs-queries", "qcoin-k"], DataTables = [""];

    public static Report Run(SupersamplingResultsSettings settings, Action<string> progress)
    {
        progress($"error against queries over {settings.Trials} means");
        var points = SupersamplingBenchmark.ErrorVersusQueries(settings.Trials, settings.Seed);
        var report = new Report(Title);
        report.Text($"Mean absolute error over {settings.Trials} uniform random means f (one subpixel of value f; the analytic engine samples the exact outcome distributions, and the tests show the fullstate engine agrees with them). Queries per docs/conventions.md: a coin flip 1, a Grover operator 2, QSS 2^(t+1) − 1. Seed {settings.Seed}.");
        report.Text("""
            MLAE: the default schedule (m = 0, 1, 2, 3, 5, 8, … growing by 1.5, m = 0 and 1 with twice the flips, K the largest with ≥ 8 flips per level)
            and Suzuki et al.'s doubling schedule (m = 0, 1, 2, 4, …, equal flips, K the largest with ≥ 12 flips per level).
            """);

        var bestQCoin = SupersamplingBenchmark.Best(points, "qcoin");
        var bestMlae = SupersamplingBenchmark.Best(points, "mlae");
        var bestDoubling = SupersamplingBenchmark.Best(points, "mlae-doubling");
        var defaults = new List<Point>();
        var doublingDefaults = new List<Point>();
        var byQueries = new TextTable("error-vs-queries", ["queries", "MC", "QCoin k=3", "k=4", "k=5", "k=6", "QCoin best (k)", "MLAE default (K)", "MLAE best (K)", "MLAE doubling, default (K)", "doubling, best (K)"]);
        foreach (var q in SupersamplingBenchmark.QueryLevels)
        {
            string Cell(string method, int parameter) => points.FirstOrDefault(p => p.Method == method && p.Parameter == parameter && p.Queries == q) is { } p ? E(p.MeanError) : "–";
            var defaultMlae = points.First(p => p.Method == "mlae" && p.Parameter == MlaeSchedule.Default.DefaultLevels(q) && p.Queries == q);
            var defaultDoubling = points.First(p => p.Method == "mlae-doubling" && p.Parameter == MlaeSchedule.Doubling.DefaultLevels(q) && p.Queries == q);
            defaults.Add(defaultMlae);
            doublingDefaults.Add(defaultDoubling);
            byQueries.Row(N(q), Cell("mc", 0), Cell("qcoin", 3), Cell("qcoin", 4), Cell("qcoin", 5), Cell("qcoin", 6), WithParameter(bestQCoin.First(p => p.Queries == q)),
                WithParameter(defaultMlae), WithParameter(bestMlae.First(p => p.Queries == q)), WithParameter(defaultDoubling), WithParameter(bestDoubling.First(p => p.Queries == q)));
        }
        report.Table(byQueries);

        var qss = points.Where(p => p.Method == "qss").ToList();
        var mc = points.Where(p => p.Method == "mc").ToList();
        report.Text("QSS for continuous values, estimate sin²(πy/2^t):");
        var continuous = new TextTable("qss-continuous", ["counter bits t", "queries", "mean abs error"]);
        foreach (var p in qss) continuous.Row(N(p.Parameter), N(p.Queries), E(p.MeanError));
        report.Table(continuous);

        report.Text("Log-log slopes of error against queries (least squares over the query levels in the range):");
        var slopes = new TextTable("slopes", ["series", "240..3200", "60..3200"]);
        foreach (var (name, series) in new (string, IEnumerable<Point>)[]
        {
            ("MC", mc), ("QCoin best k", bestQCoin), ("MLAE default K", defaults), ("MLAE best K", bestMlae),
            ("MLAE doubling, default K", doublingDefaults), ("MLAE doubling, best K", bestDoubling), ("QSS", qss),
        })
            slopes.Row(name, Slope(series, 240, 3200), Slope(series, 60, 3200));
        report.Table(slopes);

        progress("QSS lookup tables");
        report.Text("QSS lookup table (binary subpixels, hit counts 0..N equally likely), exact table, against Monte Carlo with 2^t − 1 samples rounded to a hit count:");
        var lookup = new TextTable("qss-lookup-table", ["subpixels N", "counter bits t", "QSS mean error (hits)", "QSS exact share", "MC samples", "MC mean error (hits)", "MC exact share"]);
        foreach (var (n, t) in new[] { (16, 4), (16, 5), (64, 7), (64, 8) })
        {
            var (qssError, qssExact) = SupersamplingBenchmark.TableAccuracy(QssLookupTable.Exact(n, t));
            var samples = (1 << t) - 1;
            var (mcError, mcExact) = SupersamplingBenchmark.MonteCarloHitAccuracy(n, samples);
            lookup.Row(N(n), N(t), F(qssError, "0.000"), F(qssExact, "0.0%"), N(samples), F(mcError, "0.000"), F(mcExact, "0.0%"));
        }
        report.Table(lookup);

        report.Text("Error against queries, log-log (the QCoin paper's fig. 8 left and right; slopes fitted over 240..3200, QSS over its levels 255..2047):");
        report.Plot("error-vs-queries", Plot("Mean absolute error against queries",
        [
            Series("MC", mc, 240, 3200), Series("QSS (continuous)", qss, 255, 2047), Series("QCoin, best k", bestQCoin, 240, 3200),
            Series("MLAE, default K", defaults, 240, 3200), Series("MLAE doubling, default K", doublingDefaults, 240, 3200),
        ]), "error against queries");
        report.Text("QCoin for fixed k (fig. 8 centre): each k follows slope ≈ −1 once its steps have enough flips, then bends towards −0.5; the best k grows with the budget.");
        report.Plot("qcoin-k", Plot("QCoin by number of steps k",
        [
            Series("MC", mc, 240, 3200), .. Enumerable.Range(3, 4).Select(k => Series($"QCoin k = {k}", points.Where(p => p.Method == "qcoin" && p.Parameter == k).ToList())),
            Series("QCoin, best k", bestQCoin, 240, 3200),
        ]), "QCoin by k");

        var data = new TextTable(null, ["method", "parameter", "queries", "mean_abs_error"]);
        foreach (var p in points) data.Row(p.Method, N(p.Parameter), N(p.Queries), F(p.MeanError, "G6"));
        report.Data(data);
        return report;
    }

    // Labelled with the fitted slope over [from, to]; a fixed-k QCoin series gets none, its slope changes along the curve.
    private static PlotSeries Series(string name, IReadOnlyList<Point> points, long from = 0, long to = 0) =>
        new(to == 0 ? name : $"{name} (slope {F(SupersamplingBenchmark.Slope(points, from, to), "0.00")})",
            [.. points.OrderBy(p => p.Queries).Select(p => ((double)p.Queries, p.MeanError))]);

    private static PlotSpec Plot(string title, IReadOnlyList<PlotSeries> series) =>
        new(title, "queries per estimate (a flip 1, a Grover operator 2)", "mean absolute error", AxisScale.Log10, AxisScale.Log10, series);

    private static string WithParameter(Point p) => $"{E(p.MeanError)} ({p.Parameter})";

    private static string Slope(IEnumerable<Point> points, long from, long to) => F(SupersamplingBenchmark.Slope(points, from, to), "0.000");

    private static string E(double value) => F(value, "0.00000");

    private static string F(double value, string format) => value.ToString(format, CultureInfo.InvariantCulture);

    private static string N(long value) => value.ToString(CultureInfo.InvariantCulture);
}
