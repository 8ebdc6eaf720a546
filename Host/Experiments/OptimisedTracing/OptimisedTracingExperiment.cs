using System.Globalization;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Generation;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// `bench optimised-tracing`: the paper's sec. 6 on our renderer — NeighOpt by iterations (table 5), false-negative
/// estimates (table 6), scalability of the optimised renderer (table 7), randomized classical against quantum
/// at equal Int/Ray (table 8) — and our default configuration beside the classical engine run through the same
/// pipeline (docs/optimised-tracing.md).
/// </summary>
public static class OptimisedTracingExperiment
{
    public const string Title = "Optimised tracing: neighbours, termination, lattice";

    public static Report Run(OptimisedTracingSettings settings, Action<string> progress)
    {
        var (size, seed) = (settings.Size, settings.Seed);
        var paper = new QSearchOptions(Rule: MSetRule.Round);
        var ours = new QSearchOptions();
        var plain = RenderOptions.PaperPipeline(size, size, seed);
        // The paper's optimised renderer: NeighOpt on primary and specular rays, termination with its p̄, up to 8 rounds.
        var paperOptimised = plain with { Iterations = 8, Neighbours = true, Stop = StopMode.Paper };
        var best = RenderDefaults.Options(size, size, seed);
        RenderMeasurement Measure(Scene scene, EngineKind kind, RenderOptions options, QSearchOptions qsearch) =>
            RenderMeasurement.Run(scene, new EngineSetup(kind, qsearch, settings.Workers), options, RenderMeasurement.Reference(scene, options));

        var report = new Report(Title);
        report.Text($"""
            {size}x{size} pixels, seed {seed}, analytic engine (exact outcome distributions), strict ties. Error against the classical render
            (NRMSE = RMS of 8-bit differences / reference range; #Dpix = pixels whose 8-bit RGB differs). #Cpix = rays whose result neighbour
            gathering changed. *Paper count*: r per Grover run, M_l = round(c^l) (table 6); *conservative*: r + 1, Algorithm 1's M_l (docs/conventions.md).
            """);

        report.Heading("NeighOpt by TracePass iterations (the paper's table 5; no termination, paper count)");
        var table5 = new TextTable("table-5", ["scene", "#It", "Int/Ray", "NRMSE", "#Dpix", "#Cpix"]);
        foreach (var stem in new[] { "qornell-64", "depth-complexity-64" })
        {
            var scene = settings.Scene(stem);
            for (var it = 1; it <= 4; it++)
            {
                progress($"table 5: {stem}, {it} iterations");
                var m = Measure(scene, EngineKind.Analytic, plain with { Iterations = it, Neighbours = true }, paper);
                table5.Row(stem, N(it), F(m.Result.Total.PerRayPaper), P(m.Error.Nrmse, "P1"), N(m.Error.DifferentPixels), N(m.Result.Total.UpdatedPixels));
            }
        }
        report.Table(table5);

        report.Heading("False-negative probability of one search, p̄ (the paper's table 6, c = 1.8)");
        // The paper's table 6 against eq. 10 at r = M_l: close everywhere but N = 32, where the round rule's set ends earlier than the paper's.
        var deviation = PaperNumbers.Table6.Where(e => e.Key != 32)
            .Max(e => Math.Abs(FalseNegativeRate.Eq10AtBound(new QSearchSchedule(e.Key, rule: MSetRule.Round), FalseNegativeRate.Uniform(e.Key, e.Key)) - e.Value));
        var at32 = FalseNegativeRate.Eq10AtBound(new QSearchSchedule(32, rule: MSetRule.Round), FalseNegativeRate.Uniform(32, 32));
        var at32PaperSet = FalseNegativeRate.Eq10AtBound(QSearchSchedule.Fixed(32, [1, 2, 3, 6]), FalseNegativeRate.Uniform(32, 32));
        report.Text($$"""
            Eq. 10 as printed uses cos²((M_l + 1)θ); evaluated at r = M_l, cos²((2M_l + 1)θ), it reproduces the paper's table 6 within {{F3(deviation)}} at every N but 32.
            At N = 32 `--m-rule round` stops at M = {1, 2, 3} (round(1.8³) = 6 is not below ceil(√32) = 6), and eq. 10 at r = M gives {{F3(at32)}} against the paper's
            {{F3(PaperNumbers.Table6[32])}}; the paper's value implies the set {1, 2, 3, 6}, for which eq. 10 at r = M gives {{F3(at32PaperSet)}}.
            *Exact* is the miss rate of our QSearch (the initial sample, then r_l uniform on 1..M_l), for t uniform on 1..N, computed and
            measured (20,000 searches with t drawn uniformly, analytic engine). The last column uses t as it occurs on the Qornell box 64
            (measured classically on a lattice of primary rays, see `--stop scene`): real scenes have small t, where QSearch misses most.
            """);
        var table6 = new TextTable("table-6", ["N", "M (round)", "paper's table 6", "eq. 10 as printed", "eq. 10 at r = M", "exact, round", "exact, Alg. 1 (ceiling)", "measured, Alg. 1", "exact, Alg. 1, Qornell-64 t"]);
        var qornell64 = settings.Scene("qornell-64");
        var (scenePt, _) = SceneTDistribution.Measure(new Intersection.SceneGeometry(qornell64), Rays.CameraRays.For(qornell64.Camera, size, size), size, size);
        foreach (var (n, published) in PaperNumbers.Table6)
        {
            progress($"table 6: N = {n}");
            var round = new QSearchSchedule(n, rule: MSetRule.Round);
            var ceiling = new QSearchSchedule(n);
            var uniform = FalseNegativeRate.Uniform(n, n);
            var sceneColumn = n == 64 ? F3(FalseNegativeRate.QSearchExact(ceiling, scenePt)) : "";
            table6.Row(N(n), round.ToString(), F3(published), F3(FalseNegativeRate.Eq10AsPrinted(round, uniform)), F3(FalseNegativeRate.Eq10AtBound(round, uniform)),
                F3(FalseNegativeRate.QSearchExact(round, uniform)), F3(FalseNegativeRate.QSearchExact(ceiling, uniform)), F3(MeasuredMissRate(ceiling, seed)), sceneColumn);
        }
        report.Table(table6);

        report.Heading("Scalability, optimised (the paper's table 7)");
        report.Text($"""
            *Paper's configuration*: NeighOpt on primary and specular rays, termination with the paper's p̄, up to 8 rounds, paper count.
            *Our default* (`render` with no options): NeighOpt, occluder gathering for shadow rays, termination with the exact p̄, up to {RenderDefaults.Iterations} rounds, a lattice of
            {RenderDefaults.LatticeLevelsFor(size, size)} levels (from the image size) traced first with cheap confirmations (miss ≤ {RenderDefaults.AgreedMiss} for t ≤ {ConfirmationPlanner.MaxT}) where all coarser neighbours agree,
            and rays no neighbour vouches for stopped only after the misses the {AccuracyBudget.Target:P1} accuracy budget asks (docs/rendering.md), conservative count. *Classical, same pipeline*:
            the classical engine through our default configuration — what the pipeline saves without any quantum search (docs/conventions.md).
            """);
        var table7 = new TextTable("table-7", ["scene", "N", "paper's config: Int/Ray (paper count)", "#Dpix", "paper's table 7: Int/Ray", "#Dpix", "our default: Int/Ray (conservative)", "#Dpix", "classical, same pipeline: Int/Ray", "analytic / classical wall time"]);
        var fit = new List<(double N, double IntPerRay)>();
        foreach (var stem in PaperNumbers.Optimised.Keys)
        {
            progress($"table 7: {stem}");
            var scene = settings.Scene(stem);
            var p = Measure(scene, EngineKind.Analytic, paperOptimised, paper);
            var o = Measure(scene, EngineKind.Analytic, best, ours);
            var c = Measure(scene, EngineKind.Classical, best, ours);
            var (publishedIntPerRay, publishedDpix) = PaperNumbers.Optimised[stem];
            table7.Row(stem, N(scene.Primitives.Count), F(p.Result.Total.PerRayPaper), N(p.Error.DifferentPixels), F(publishedIntPerRay), N(publishedDpix),
                F(o.Result.Total.PerRayConservative), N(o.Error.DifferentPixels), F(c.Result.Total.PerRayConservative), P(o.WallTime / c.WallTime, "0.0") + "x");
            if (stem.StartsWith("qornell", StringComparison.Ordinal)) fit.Add((scene.Primitives.Count, o.Result.Total.PerRayConservative));
        }
        progress("table 7: qornell-4096 (built in)");
        var large = SceneLoader.Parse(QornellBox.Build(4096).ToJson(), "built-in qornell-4096");
        var l = Measure(large, EngineKind.Analytic, best, ours);
        table7.Row("qornell-4096 (built in)", "4096", "", "", "", "", F(l.Result.Total.PerRayConservative), N(l.Error.DifferentPixels), "", "");
        report.Table(table7);
        report.Text($"Int/Ray of our default over the Qornell box N = 8..512 grows as N^{P(LogLogSlope(fit), "0.00")} (least-squares fit of log Int/Ray on log N); sqrt(N) would be N^0.50.");

        report.Heading("Randomized classical against quantum at equal Int/Ray (the paper's table 8, Qornell 64)");
        report.Text("""
            For each version the quantum render uses 4 rounds (8 with termination); the randomized renderer gets the number of rounds that brings
            its Int/Ray closest to the quantum one (paper count, the paper's p̄ for termination: eq. 11 for the randomized engine). With termination the
            randomized renderer stops most rays after one miss (p̄_RC ≈ 0.12), so more rounds cannot raise its Int/Ray to the quantum one: the row
            then compares at the most it spends. The randomized renderer runs without the accuracy budget (our default row included): under
            the budget it settles its rays classically and its rounds no longer set its cost.
            """);
        var table8 = new TextTable("table-8", ["version", "quantum Int/Ray", "quantum NRMSE", "randomized #It", "randomized Int/Ray", "randomized NRMSE", "NRMSE ratio", "paper: Q NRMSE", "paper: RC NRMSE"]);
        var versions = new[]
        {
            plain,
            plain with { Neighbours = true },
            plain with { Iterations = 8, Neighbours = true, Stop = StopMode.Paper },
            best with { Stop = StopMode.Paper },
        };
        for (var v = 0; v < versions.Length; v++)
        {
            progress($"table 8: version {v + 1}/{versions.Length}");
            var q = Measure(qornell64, EngineKind.Analytic, versions[v], paper);
            var (closest, closestIt) = ClosestRandomized(qornell64, versions[v], q.Result.Total.PerRayPaper, r => Measure(qornell64, EngineKind.Randomized, r, paper));
            var (version, paperQ, paperRc) = v < PaperNumbers.Randomized.Count
                ? (PaperNumbers.Randomized[v].Version, P(PaperNumbers.Randomized[v].QNrmse, "P1"), P(PaperNumbers.Randomized[v].RcNrmse, "P1"))
                : ("our default pipeline (paper's p̄)", "", "");
            // An exact quantum render has NRMSE 0: the ratio is then shown as ∞.
            var ratio = q.Error.Nrmse > 0 ? P(closest.Error.Nrmse / q.Error.Nrmse, "0") + "x" : "∞";
            table8.Row(version, F(q.Result.Total.PerRayPaper), P(q.Error.Nrmse, "P2"), N(closestIt), F(closest.Result.Total.PerRayPaper), P(closest.Error.Nrmse, "P2"),
                ratio, paperQ, paperRc);
        }
        report.Table(table8);
        return report;
    }

    // The randomized render, over 1..24 rounds, whose Int/Ray (paper count) is closest to the quantum one; it stops once a render spends 20% more.
    private static (RenderMeasurement Closest, int Iterations) ClosestRandomized(Scene scene, RenderOptions version, double target, Func<RenderOptions, RenderMeasurement> measure)
    {
        RenderMeasurement? closest = null;
        var closestIt = 0;
        for (var it = 1; it <= 24; it++)
        {
            // Without the accuracy budget: under it the randomized renderer settles its rays classically (N tests each), and its
            // rounds would no longer set its cost.
            var r = measure(version with { Iterations = it, ShadowIterations = Math.Max(2, it / 2), Budget = null });
            if (closest is null || Math.Abs(r.Result.Total.PerRayPaper - target) < Math.Abs(closest.Result.Total.PerRayPaper - target))
                (closest, closestIt) = (r, it);
            if (r.Result.Total.PerRayPaper > target * 1.2) break;
        }
        return (closest!, closestIt);
    }

    // QSearch's miss rate measured on the analytic engine: 20,000 searches, t uniform on 1..N.
    private static double MeasuredMissRate(QSearchSchedule schedule, ulong seed)
    {
        const int searches = 20_000;
        var random = new SeededRandom(seed).Fork(RandomStreams.Scenario);
        using var engine = new AnalyticEngine(new SeededRandom(seed).Fork(RandomStreams.Engine));
        var shared = new SeededRandom(seed).Fork(RandomStreams.Search);
        var runs = Enumerable.Range(0, searches)
            .Select(_ => new QSearch(new MarkedSet(schedule.Count, Enumerable.Range(0, random.NextInt(1, schedule.Count))), schedule, shared))
            .ToArray();
        QSearchDriver.Run(runs, engine);
        return (double)runs.Count(s => s.Found is null) / searches;
    }

    private static double LogLogSlope(IReadOnlyList<(double X, double Y)> points)
    {
        var xs = points.Select(p => Math.Log(p.X)).ToArray();
        var ys = points.Select(p => Math.Log(p.Y)).ToArray();
        var (mx, my) = (xs.Average(), ys.Average());
        return xs.Zip(ys).Sum(p => (p.First - mx) * (p.Second - my)) / xs.Sum(x => (x - mx) * (x - mx));
    }

    private static string F(double value) => value.ToString("0.0", CultureInfo.InvariantCulture);

    private static string F3(double value) => value.ToString("0.000", CultureInfo.InvariantCulture);

    private static string N(long value) => value.ToString(CultureInfo.InvariantCulture);

    private static string P(double value, string format) => value.ToString(format, CultureInfo.InvariantCulture);
}
