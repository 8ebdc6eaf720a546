using System.Globalization;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Output;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Reports;
using static QuantumRayTracing.Experiments.LightTransportExperiment;

namespace QuantumRayTracing.Experiments;

/// <summary>Composes docs/light-transport.md from <see cref="LightTransportExperiment"/>'s measurements.</summary>
public static class LightTransportReport
{
    /// <summary>The error the queries-to-target column reads the fitted lines at: 1 % NRMSE against the exact mean.</summary>
    public const double Target = 0.01;

    private const string Queries = "queries per point and light";

    private const string XLabel = "queries per point and light (a flip 1, a Grover operator 2)";

    public static Report Build(LightTransportSettings settings, IReadOnlyList<Cell> cells, IReadOnlyList<Traced> traced,
        IReadOnlyDictionary<LightEstimator, ConvergenceFit?> fits, Images? images)
    {
        var converged = Estimators.ToDictionary(e => e, e => Fit(cells, e, c => c.Converged));
        var seeds = settings.Seeds == 1 ? "seed 1" : $"seeds 1..{settings.Seeds}";
        var points = $"{settings.Queries.Count} query counts ({string.Join(", ", settings.Queries.Select(q => N(q)))})";
        var report = new Report(LightTransportExperiment.Title);
        report.Text($"""
            Our own comparison (not a paper's figure): each shading point's area light as the mean over its fixed set of {settings.AreaSamples}
            samples (docs/rendering.md, *Quantum light estimation*), read by Monte Carlo (`mc`: Q samples drawn uniformly from the set, with
            replacement) and by each quantum estimator (`qcoin`, `mlae`, `iqae`, `bae`, their default parameters), on
            {settings.SceneFile} at {settings.Size}x{settings.Size} pixels, `render`'s default pipeline on the analytic engine (each estimator's
            outcomes drawn from its exact distributions, seeded), {seeds}, {points}. Queries are counted as docs/conventions.md counts
            mean estimation: a coin flip 1, a Grover operator 2, a Monte Carlo sample 1; the budget is per shading point and light.
            Two errors per render: the **light error against the exact mean** of each point's samples (RMS over every shading point's
            area-light irradiance channels of the estimate minus the exact mean of its set, every sample evaluated classically, over the
            exact values' range; what `render` prints), where nothing floors the error; and the **image NRMSE against the converged
            classical reference** ({settings.ReferenceSamples} area samples per point; 8-bit channels, docs/conventions.md), which also holds
            the set's own discretisation error, the primary searches' errors and 8-bit rounding.
            """);

        report.Heading("Light error against the exact mean of each point's samples");
        report.Text($"NRMSE, geometric mean over the seeds (the fit below is a line through the logarithms), by {Queries}:");
        report.Table(ByQueries("exact", settings, cells, c => c.Exact));
        report.Plot("exact", Plot("Light error against the exact mean of each point's samples", "light NRMSE against the exact mean (%)", settings, cells, fits, c => c.Exact,
            [new PlotSeries("1 %", [.. Ends(settings).Select(q => (q, Target * 100))], Markers: false)]), "light error against queries, log-log");

        report.Heading("Fitted slopes and the queries to 1 %");
        report.Text($"""
            These are fits: each seed's least-squares line of log10 NRMSE on log10 queries over the {points}, averaged over the {seeds}
            (the least-squares line through every seed's points); the interval is the 95 % Student-t interval of the mean slope over the
            seeds' slopes ({settings.Seeds - 1} degree{(settings.Seeds == 2 ? "" : "s")} of freedom). The queries to 1 % NRMSE against the exact mean are read on that
            fitted line: *interpolated* inside the measured range {N(settings.Queries.Min())}..{N(settings.Queries.Max())}, *extrapolated*
            outside it. The last column fits the image error against the converged reference the same way; it flattens where the set's
            discretisation error and the searches' errors take over.
            """);
        report.Table(Slopes(settings, fits, converged));
        Targets(report, settings, fits);

        report.Heading("Image error against the converged reference");
        var floor = Geometric(traced.Select(t => t.Converged));
        report.Text($"""
            Image NRMSE against the converged classical reference, geometric mean over the seeds, by {Queries}. The classical render with every
            sample of each set traced (the exact means, no search error) lies at {P(floor)} from it: the floor of sets of {settings.AreaSamples} samples.
            """);
        report.Table(ByQueries("converged", settings, cells, c => c.Converged));
        report.Plot("converged", Plot("Image error against the converged classical reference", "image NRMSE against the converged reference (%)", settings, cells, converged, c => c.Converged,
            [new PlotSeries("every sample traced", [.. Ends(settings).Select(q => (q, floor * 100))], Markers: false)]), "image error against the converged reference, log-log");

        if (images is not null) ImageSection(report, settings, images);

        report.Heading("Every measurement");
        var spent = cells.Where(c => c.Estimator != LightEstimator.Mc).MinBy(c => c.Spent);
        report.Text($"""
            Each render's errors, and the queries it spent as a share of its budget (Monte Carlo's queries at the same seed and budget, which
            spends exactly its budget on every lit set): IQAE and BAE may stop below it{(spent is null ? "" : $"; the least any quantum estimator spent was {spent.Spent.ToString("P1", CultureInfo.InvariantCulture)} ({Name(spent.Estimator)} at {N(spent.Queries)}, seed {spent.Seed})")}.
            """);
        var table = new TextTable("cells", ["estimator", Queries, "seed", "light NRMSE, exact mean", "image NRMSE, converged", "queries spent / budget"]).AlignRight(1, 2, 3, 4, 5);
        foreach (var c in cells.OrderBy(c => Array.IndexOf(Estimators, c.Estimator)).ThenBy(c => c.Queries).ThenBy(c => c.Seed))
            table.Row(Name(c.Estimator), N(c.Queries), c.Seed.ToString(CultureInfo.InvariantCulture), P(c.Exact), P(c.Converged), c.Spent.ToString("0.000", CultureInfo.InvariantCulture));
        report.Table(table);
        return report;
    }

    private static TextTable ByQueries(string name, LightTransportSettings settings, IReadOnlyList<Cell> cells, Func<Cell, double> error)
    {
        var table = new TextTable(name, [Queries, .. Estimators.Select(Name)]).AlignRight(Enumerable.Range(0, Estimators.Length + 1));
        foreach (var q in settings.Queries)
            table.Row([N(q), .. Estimators.Select(e => P(Geometric(cells.Where(c => c.Estimator == e && c.Queries == q).Select(error))))]);
        return table;
    }

    private static TextTable Slopes(LightTransportSettings settings, IReadOnlyDictionary<LightEstimator, ConvergenceFit?> fits, IReadOnlyDictionary<LightEstimator, ConvergenceFit?> converged)
    {
        var table = new TextTable("slopes", ["estimator", "fitted slope", "95 % interval", "seeds' slopes", "queries to 1 %", "read", "Monte Carlo's queries / these", "slope against the converged reference"]);
        var mc = fits[LightEstimator.Mc]?.QueriesTo(Target);
        foreach (var e in Estimators)
        {
            if (fits[e] is not { } fit)
            {
                table.Row(Name(e), "–", "–", "–", "–", "–", "–", "–");
                continue;
            }
            var to = fit.QueriesTo(Target);
            var read = to is not { } q ? "–" : q >= settings.Queries.Min() && q <= settings.Queries.Max() ? "interpolated" : "extrapolated";
            table.Row(Name(e), S(fit.Slope), fit.HalfWidth is { } h ? $"{S(fit.Slope - h)} .. {S(fit.Slope + h)}" : "– (one seed)",
                $"{S(fit.SeedSlopes.Min())} .. {S(fit.SeedSlopes.Max())}", to is { } t ? N((long)Math.Round(t)) : "–", read,
                mc is { } m && to is { } t2 ? (m / t2).ToString("0.0", CultureInfo.InvariantCulture) : "–", converged[e] is { } c ? S(c.Slope) : "–");
        }
        return table;
    }

    // The issue's targets, each stated as met or not from the fits above.
    private static void Targets(Report report, LightTransportSettings settings, IReadOnlyDictionary<LightEstimator, ConvergenceFit?> fits)
    {
        if (fits[LightEstimator.Mc] is not { } mc) return;
        var quantum = Estimators.Skip(1).Where(e => fits[e] is not null).Select(e => (Estimator: e, Fit: fits[e]!)).ToArray();
        string Slope(ConvergenceFit f) => f.HalfWidth is { } h ? $"{S(f.Slope)} (95 %: {S(f.Slope - h)} .. {S(f.Slope + h)})" : S(f.Slope);
        var steep = quantum.Select(q => $"{Name(q.Estimator)} {Slope(q.Fit)}: " + (q.Fit.Slope <= -0.9
            ? q.Fit.HalfWidth is { } h && q.Fit.Slope + h > -0.9 ? "met by the fit, its interval reaches above −0.9" : "met"
            : "not met")).ToArray();
        var best = Best(fits);
        var ratio = mc.QueriesTo(Target) / fits[best]?.QueriesTo(Target);
        report.Text($"""
            **Against the targets** set for this comparison, from the fits above ({settings.Size}x{settings.Size}, {settings.Seeds} seed{(settings.Seeds == 1 ? "" : "s")}):
            a quantum slope of at most −0.9 — {string.Join("; ", steep)}. Monte Carlo about −0.5 — {Slope(mc)}. 1 % reached with at least
            10 times fewer queries than Monte Carlo — the best quantum estimator, {Name(best)}, needs {(ratio is { } r ? $"{r.ToString("0.0", CultureInfo.InvariantCulture)} times fewer: {(r >= 10 ? "met" : "not met")}" : "no fitted crossing: not met")}.{TenTimes(mc, fits[best], best)}
            """);
    }

    // Where, on the fitted lines, Monte Carlo would need ten times the queries of the best quantum estimator (an extrapolation when outside the measured range).
    private static string TenTimes(ConvergenceFit mc, ConvergenceFit? best, LightEstimator name) =>
        best?.QueriesTo(Target) is not null && mc.ErrorAtQueriesRatio(best, 10) is { } error && best.QueriesTo(error) is { } queries
            ? $" On the fitted lines the ratio reaches 10 at an NRMSE of {P(error)}, where {Name(name)} needs about {N((long)Math.Round(queries))} queries (read on the lines, not measured)."
            : "";

    private static void ImageSection(Report report, LightTransportSettings settings, Images images)
    {
        var size = images.Traced.Width;
        var best = Name(images.Best);
        report.Heading("Images at equal queries");
        report.Text($"""
            {size}x{size}, seed 1: Monte Carlo and the quantum estimator with the fewest queries to 1 % on its fitted line ({best}) at equal
            queries per point and light, one row per count, then the classical render with every sample of each set traced (the exact means
            the light error is measured against) and the converged reference. Light NRMSE against the exact mean:
            {string.Join("; ", images.Pairs.Select(p => $"at {N(p.Queries)} queries Monte Carlo {P(p.Mc.LightError!.Nrmse)}, {best} {P(p.Quantum.LightError!.Nrmse)}"))}.
            """);
        foreach (var pair in images.Pairs)
            report.ImageRow([
                new ReportImage($"image-{pair.Queries}-mc", pair.Mc.Image, $"Monte Carlo, {N(pair.Queries)} queries"),
                new ReportImage($"image-{pair.Queries}-quantum", pair.Quantum.Image, $"{best}, {N(pair.Queries)} queries"),
            ]);
        report.ImageRow([
            new ReportImage("image-traced", images.Traced, $"every sample traced ({settings.AreaSamples} per point)"),
            new ReportImage("image-converged", images.Converged, $"converged reference ({settings.ReferenceSamples} samples)"),
        ]);
    }

    private static PlotSpec Plot(string title, string yLabel, LightTransportSettings settings, IReadOnlyList<Cell> cells,
        IReadOnlyDictionary<LightEstimator, ConvergenceFit?> fits, Func<Cell, double> error, IEnumerable<PlotSeries> lines)
    {
        var series = Estimators.Select(e => new PlotSeries(
            $"{Name(e)}{(fits[e] is { } f ? $" (fitted slope {S(f.Slope)})" : "")}",
            [.. settings.Queries.Select(q => ((double)q, 100 * Geometric(cells.Where(c => c.Estimator == e && c.Queries == q).Select(error))))]));
        return new PlotSpec(title, XLabel, yLabel, AxisScale.Log10, AxisScale.Log10, [.. series, .. lines]);
    }

    private static double[] Ends(LightTransportSettings settings) => [settings.Queries.Min(), settings.Queries.Max()];

    /// <summary>exp(mean ln x): the average a line through the logarithms passes through.</summary>
    private static double Geometric(IEnumerable<double> values) => Math.Exp(values.Average(Math.Log));

    /// <summary>A percentage with four significant digits.</summary>
    public static string P(double value) => (100 * value).ToString("G4", CultureInfo.InvariantCulture) + " %";

    private static string S(double slope) => slope.ToString("0.00", CultureInfo.InvariantCulture);

    private static string N(long value) => value.ToString("N0", CultureInfo.InvariantCulture);
}
