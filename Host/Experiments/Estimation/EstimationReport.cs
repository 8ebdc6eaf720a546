using System.Globalization;
using QuantumRayTracing.Output;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;
using Point = QuantumRayTracing.Experiments.EstimationExperiment.Point;

namespace QuantumRayTracing.Experiments;

/// <summary>Composes docs/estimation.md from <see cref="EstimationExperiment"/>'s points.</summary>
public static class EstimationReport
{
    public const string Title = "Estimation";

    /// <summary>The report's plots and data tables, by name, for checking their files before the work.</summary>
    public static readonly string[] Pictures = ["means", "pixels", "noise"], DataTables = [""];

    private static readonly string[] Fitted = ["MC", "QCoin", "MLAE", "IQAE", "IQAE, original", "FAE", "BAE", "power-law", EstimationExperiment.QssBayes, EstimationExperiment.Qss, EstimationExperiment.QssPlanes];

    public static Report Build(IReadOnlyList<Point> points, EstimationSettings settings)
    {
        var report = new Report(Title);
        report.Text($"""
            Every mean estimator on one harness: the analytic engine (the circuits' exact outcome distributions, seeded), the mean coin
            of each item's subpixel values, a budget of queries per estimate. Queries as docs/conventions.md (a coin flip 1, a Grover
            operator 2, a QSS run 2^(t+1) − 1, a single-ancilla shot at power k 1 + 2k); IQAE, FAE, BAE and QSS with Bayesian PE may stop below the budget, so the plots put each point at the queries
            it spent on average, and the tables give the budget, the queries spent and the Grover operators alone (the count the AE
            papers give as oracle calls). Inputs: {settings.Trials} uniform random means in [0, 1] (one subpixel each), and the
            {settings.ImageSize}x{settings.ImageSize} pixels of the built-in Qornell box (4x4 subpixels each, rendered classically; each
            pixel and channel one estimate, {settings.ImageSize * settings.ImageSize * 3} in all). Error: absolute, against the exact mean;
            mean, median and 95th percentile over the estimates. Seed {settings.Seed}.
            """);
        report.Text("""
            Estimators (docs/supersampling.md): Monte Carlo (MC); QCoin with the measured best k; MLAE with the default K; IQAE
            (Clopper–Pearson, N = 32 flips per round, α = 0.05, the last round rerun at a fixed k on at least 40% of the budget against the
            bias) and the original IQAE (no rerun, estimate the last interval's middle); FAE (N1 = N2 = 8, on the coin rescaled to
            f/4); BAE (512-point grid posterior, power by expected variance reduction per query, posterior median); power-law AE
            (β = 0.3, 2 flips per k, maximum likelihood); QSS on continuous values (t = 3..10, estimate sin²(πy/2^t)); QSS with
            Bayesian phase estimation (*QSS, Bayesian PE*, `qss-bayes`: one ancilla controlling k Grover operators, read in the X
            basis, 0 with probability cos²(kθ); BAE's grid posterior and power choice; 1 + 2k queries a shot; noiseless only).
            """);
        foreach (var input in new[] { "means", "pixels" })
        {
            var set = points.Where(p => p.Input == input && p.Noiseless).ToList();
            report.Heading(input == "means" ? "Uniform random means" : "The Qornell box's pixels");
            ErrorTables(report, set);
            Fits(report, set);
            report.Text("Error against queries, log-log; the slope in each label is a least-squares fit over the budgets 240..3200:");
            report.Plot(input, Plot(input == "means" ? "Mean absolute error, uniform random means" : "Mean absolute error, Qornell box pixels", set, input == "means"),
                input == "means" ? "error against queries, random means" : "error against queries, Qornell box pixels");
            Tail(report, set);
        }
        var noisy = points.Where(p => p.Decay > 0).ToList();
        if (noisy.Count > 0)
        {
            report.Heading("Under noise");
            report.Text("""
                The same uniform random means under depolarizing decay γ per Grover operator: the direct single-qubit coin (`DirectCoinEngine`)
                with the per-gate depolarizing error that gives fidelity e^(−γ) per Grover operator, so a flip after m operators is a head with
                probability e^(−γ(m+½))·sin²((2m+1)θ) + (1 − e^(−γ(m+½)))/2. None of these estimators models the noise (mlae-noise does:
                docs/noise-estimation.md). *MC, noisy coin* flips that noisy coin without amplification, so noise biases it too; *classical
                MC* is Monte Carlo without noise, the baseline a quantum estimator must beat. Mean absolute error:
                """);
            var classical = points.Where(p => p.Input == "means" && p.Noiseless).ToList();
            var table = new TextTable("noise", ["γ", "queries", "classical MC", .. EstimationExperiment.Estimators.Select(e => e.Label == "MC" ? "MC, noisy coin" : e.Label)]);
            foreach (var decay in EstimationSettings.Decays)
                foreach (var budget in EstimationSettings.NoisyBudgets)
                    table.Row([F(decay, "0.###"), N(budget), Cell(classical, 0, "MC", budget, p => p.Mean), .. EstimationExperiment.Estimators.Select(e => Cell(noisy, decay, e.Label, budget, p => p.Mean))]);
            report.Table(table);
            report.Text("Under γ = 0.03, log-log; the slope in each label is a least-squares fit over the budgets 240..3200:");
            report.Plot("noise", new PlotSpec("Mean absolute error under decay γ = 0.03 per Grover operator", XLabel, "mean absolute error", AxisScale.Log10, AxisScale.Log10,
                [.. EstimationExperiment.Estimators.Select(e => Series(e.Label, noisy.Where(p => p.Decay == 0.03 && p.Estimator == e.Label)))]), "error against queries under noise, γ = 0.03");
        }
        var device = points.Where(p => p.OnDevice).ToList();
        if (device.Count > 0)
        {
            report.Heading("At the device's rates");
            report.Text($"""
                The same uniform random means on the direct single-qubit coin under the device model that docs/noise-estimation.md fits to
                the QCoin paper's fig. 10 ({EstimationSettings.DeviceRates.Description()}): a fit to one device's figure, not a measured
                device. Each flip reads its bit through the readout error, so even the unamplified coin (*MC, noisy coin*) is biased. Mean absolute error:
                """);
            var classical = points.Where(p => p.Input == "means" && p.Noiseless).ToList();
            var table = new TextTable("device", ["queries", "classical MC", .. EstimationExperiment.Estimators.Select(e => e.Label == "MC" ? "MC, noisy coin" : e.Label)]);
            foreach (var budget in EstimationSettings.NoisyBudgets)
                table.Row([N(budget), Cell(classical, 0, "MC", budget, p => p.Mean), .. EstimationExperiment.Estimators.Select(e => Cell(device, 0, e.Label, budget, p => p.Mean))]);
            report.Table(table);
        }
        var data = new TextTable(null, ["input", "decay", "estimator", "budget", "queries", "grover_operators", "mean", "median", "p95", "tail_share", "device"]);
        foreach (var p in points)
            data.Row(p.Input, F(p.Decay, "G6"), p.Estimator, N(p.Budget), F(p.Queries, "G6"), F(p.GroverOperators, "G6"), F(p.Mean, "G6"), F(p.Median, "G6"), F(p.Percentile95, "G6"), F(p.TailShare, "G6"), p.OnDevice ? "fig10-fit" : "");
        report.Data(data);
        return report;
    }

    private static void ErrorTables(Report report, List<Point> set)
    {
        foreach (var (name, value) in new (string, Func<Point, double>)[] { ("mean", p => p.Mean), ("median", p => p.Median), ("95th percentile", p => p.Percentile95) })
        {
            report.Text($"{char.ToUpperInvariant(name[0])}{name[1..]} absolute error by budget:");
            var table = new TextTable(null, ["budget", .. EstimationExperiment.NoiselessEstimators.Select(e => e.Label)]);
            foreach (var budget in EstimationSettings.Budgets)
                table.Row([N(budget), .. EstimationExperiment.NoiselessEstimators.Select(e => Cell(set, 0, e.Label, budget, value))]);
            report.Table(table);
        }
        report.Text("Queries spent per estimate on average / Grover operators per estimate (the AE papers' count), where they differ from the budget:");
        var spent = new TextTable(null, ["budget", .. EstimationExperiment.NoiselessEstimators.Select(e => e.Label)]);
        foreach (var budget in EstimationSettings.Budgets)
            spent.Row([N(budget), .. EstimationExperiment.NoiselessEstimators.Select(e => Cell(set, 0, e.Label, budget, p => p.Queries, p => $"{F(p.Queries, "0")} / {F(p.GroverOperators, "0")}"))]);
        report.Table(spent);
        report.Text("QSS at its own query counts (continuous values: one run, estimate sin²(πy/2^t); bit planes: 8 runs through the lookup table, pixels only):");
        var qss = new TextTable(null, ["QSS", "counter bits t", "queries", "mean", "median", "95th percentile"]);
        foreach (var p in set.Where(p => p.Estimator is EstimationExperiment.Qss or EstimationExperiment.QssPlanes).OrderBy(p => p.Estimator).ThenBy(p => p.Budget))
        {
            var runs = p.Estimator == EstimationExperiment.Qss ? 1 : SupersampleSettings.DefaultPlanes;
            qss.Row(p.Estimator == EstimationExperiment.Qss ? "continuous" : "bit planes", N((long)Math.Log2(p.Budget / runs + 1) - 1), N(p.Budget), E(p.Mean), E(p.Median), E(p.Percentile95));
        }
        report.Table(qss);
    }

    private static void Fits(Report report, List<Point> set)
    {
        report.Text("Fitted log-log slopes of the mean error against the queries spent (least squares over the budgets in the range; −0.5 is Monte Carlo's scaling, −1 Heisenberg's):");
        var fits = new TextTable(null, ["estimator", "240..3200", "15..3200"]);
        foreach (var label in Fitted)
        {
            var series = set.Where(p => p.Estimator == label).ToList();
            if (series.Count == 0) continue;
            fits.Row(label, F(EstimationExperiment.Slope(series, 240, 3200), "0.00"), F(EstimationExperiment.Slope(series, 15, 3200), "0.00"));
        }
        report.Table(fits);
    }

    private static void Tail(Report report, List<Point> set)
    {
        report.Text("The long tail: the share of estimates whose error exceeds 3 times their median error, at the budget nearest 240 and 1,000 queries (a normal error has 4.3% there, a Laplace error 12.5%):");
        var tail = new TextTable(null, ["estimator", "queries", "share", "queries", "share"]);
        foreach (var label in Fitted)
        {
            var series = set.Where(p => p.Estimator == label).ToList();
            if (series.Count == 0) continue;
            var (near240, near1000) = (Nearest(series, 240), Nearest(series, 1000));
            tail.Row(label, N(near240.Budget), F(near240.TailShare, "0.0%"), N(near1000.Budget), F(near1000.TailShare, "0.0%"));
        }
        report.Table(tail);
    }

    private static Point Nearest(List<Point> series, double budget) => series.MinBy(p => Math.Abs(Math.Log(p.Budget / budget)))!;

    private const string XLabel = "queries per estimate, spent (a flip 1, a Grover operator 2)";

    private static PlotSpec Plot(string title, List<Point> set, bool uniform)
    {
        var x = new[] { 15.0, 3200 };
        var series = Fitted.Where(l => l != "IQAE, original" && set.Any(p => p.Estimator == l)).Select(l => Series(l, set.Where(p => p.Estimator == l))).ToList();
        // Reference lines: Monte Carlo's expected error over uniform means, E√(f(1−f))·√(2/(πQ)) = (π/8)·√(2/(πQ)), and 1/Q.
        if (uniform) series.Add(new PlotSeries("MC expected, (π/8)√(2/(πQ))", [.. x.Select(q => (q, Math.PI / 8 * Math.Sqrt(2 / (Math.PI * q))))], Markers: false));
        series.Add(new PlotSeries("Heisenberg scaling, 1/Q", [.. x.Select(q => (q, 1 / q))], Markers: false));
        return new PlotSpec(title, XLabel, "mean absolute error", AxisScale.Log10, AxisScale.Log10, series);
    }

    private static PlotSeries Series(string label, IEnumerable<Point> points)
    {
        var list = points.OrderBy(p => p.Queries).ToList();
        return new PlotSeries($"{label} (slope {F(EstimationExperiment.Slope(list, 240, 3200), "0.00")})", [.. list.Select(p => (p.Queries, p.Mean))]);
    }

    private static string Cell(IEnumerable<Point> set, double decay, string label, long budget, Func<Point, double> value, Func<Point, string>? text = null) =>
        set.FirstOrDefault(p => p.Decay == decay && p.Estimator == label && p.Budget == budget) is { } p ? text?.Invoke(p) ?? E(value(p)) : "–";

    private static string E(double value) => F(value, "0.00000");

    private static string F(double value, string format) => value.ToString(format, CultureInfo.InvariantCulture);

    private static string N(long value) => value.ToString(CultureInfo.InvariantCulture);
}
