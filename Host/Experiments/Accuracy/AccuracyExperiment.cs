using QuantumRayTracing.Engines;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Scenes.Generation;
using static System.FormattableString;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// `bench accuracy`: wrong pixels and Int/Ray of the default pipeline on random scenes it was not tuned on, by image
/// size and scene kind, beside `--lattice 0` and the paper's plain pipeline, and the other ways to keep the accuracy
/// budget measured against it (docs/accuracy.md).
/// </summary>
public static class AccuracyExperiment
{
    public const string Title = "Accuracy of the default pipeline at every image size";

    // The alternatives run on every kind but the 4,000-rectangle scenes, at the small sizes where they differ, on fewer seeds.
    private const int AlternativesUpTo = 64;
    private const int AlternativeSeeds = 5;

    // How the budget's cost grows with N: scattered scenes of these sizes at one image size.
    private const int GrowthSize = 64;

    public static Report Run(AccuracySettings settings, Action<string> progress)
    {
        if (settings.GrowthOnly)
        {
            var growthReport = new Report(Title);
            Growth(growthReport, settings.Growth, settings.GrowthSeeds, progress);
            return growthReport;
        }
        var seeds = Enumerable.Range(1, settings.Seeds).Select(s => (ulong)s).ToArray();
        var configurations = AccuracyBenchmark.Standard;
        var cases = RandomScene.Kinds.SelectMany(k => settings.Sizes.Where(s => k != RandomSceneKind.Deep || s <= settings.DeepSize).Select(s => (Kind: k, Size: s))).ToArray();
        var cells = new List<AccuracyCell>();
        foreach (var (kind, size) in cases)
        {
            progress($"{KindName(kind)}, {size}x{size} ({cells.Count / configurations.Count + 1}/{cases.Length})");
            cells.AddRange(AccuracyBenchmark.Measure(kind, size, seeds, configurations));
        }

        var report = new Report(Title);
        report.Text($"""
            Random scenes the pipeline was not tuned on (`RandomScene`, {seeds.Length} seeds per kind and size), analytic engine. *Wrong pixels*: pixels whose
            8-bit RGB differs from the classical render of the same scene and size, summed over the seeds, and their share. *Expected*: the
            wrong pixels `render` prints as expected, summed over the seeds, and their share (docs/rendering.md says how it is estimated).
            Int/Ray in the conservative count (r + 1 per Grover run), over all rays of all seeds. The budget: at most {Invariant($"{AccuracyBudget.Target:P1}")} of pixels wrong,
            in expectation, which every default render holds by budget rounds (docs/rendering.md); a render that could not says so, and its row
            would say "over budget". *Default*: `render` with no options (lattice levels from the image size); *no budget*: the same without the
            budget's rounds and classical settle, its searches as configured (the cost of the binding budget is the difference in Int/Ray);
            *--lattice 0*: the default without lattice-first tracing; *paper, plain*: 4 TracePass rounds, 2 DirectPass rounds, no neighbours, no
            termination, the paper's M sets (round(c^l)). *Settled*: the default's rays settled classically (N tests each).
            """);
        var bySize = new TextTable("sizes", ["scene kind", "size", "lattice levels", .. configurations.SelectMany(c => new[] { $"{c.Name}: wrong pixels", "share", "Int/Ray" }),
            "default: expected wrong", "expected share", "settled", "budget"]);
        foreach (var group in cells.GroupBy(c => (c.Kind, c.Size)))
        {
            var row = group.ToArray();
            var size = group.Key.Size;
            var expectedShare = row[0].AllowedWrong / row[0].Pixels;
            bySize.Row([KindName(group.Key.Kind), $"{size}x{size}", Invariant($"{RenderDefaults.LatticeLevelsFor(size, size)}"),
                .. row.SelectMany(cell => new[] { Invariant($"{cell.WrongPixels} of {cell.Pixels:N0}"), Invariant($"{cell.WrongShare:P2}"), Invariant($"{cell.IntPerRay:0.0}") }),
                Invariant($"{row[0].AllowedWrong:0.0}"), Invariant($"{expectedShare:P3}"), Invariant($"{row[0].SettledRays:N0}"),
                row[0].OverBudget > 0 ? Invariant($"over budget in {row[0].OverBudget} of {row[0].Seeds}") : "kept"]);
        }
        report.Table(bySize);

        report.Heading("The Qornell box, 64 primitives (`render`'s built-in scene, seed 1)");
        var qornell = new TextTable("qornell-64", ["size", "configuration", "wrong pixels", "Int/Ray (conservative)", "expected wrong pixels"]);
        foreach (var size in new[] { 8, 128 })
        {
            progress($"qornell-64, {size}x{size}");
            var reference = RenderMeasurement.Reference(settings.Qornell, RenderOptions.PaperPipeline(size, size));
            foreach (var c in configurations)
            {
                var m = RenderMeasurement.Run(settings.Qornell, new EngineSetup(EngineKind.Analytic, c.QSearch), c.Options(size, 1), reference);
                var expected = Invariant($"{m.Result.Budget.ExpectedWrongPixels:0.0}");
                qornell.Row($"{size}x{size}", c.Name, Invariant($"{m.Error.DifferentPixels} of {size * size:N0}"), Invariant($"{m.Result.Total.PerRayConservative:0.00}"), expected);
            }
        }
        report.Table(qornell);

        Growth(report, settings.Growth, settings.GrowthSeeds, progress);

        var alternativeSizes = settings.Sizes.Where(s => s <= AlternativesUpTo).ToArray();
        var alternativeSeeds = seeds.Take(AlternativeSeeds).ToArray();
        report.Heading("The ways to keep the budget, measured");
        report.Text($"""
            Every kind but the 4,000-rectangle scenes, {alternativeSeeds.Length} seeds per kind and size; wrong pixels summed, Int/Ray (conservative) over all rays.
            Each keeps the budget by its rounds; they differ in what the passes do before the rounds. The default stops a ray after one empty
            search (the paper's rule), sizes each lattice level's cheap confirmation by the budget and lets the rounds find where more search
            is needed; *2 required misses*: every ray its neighbours do not vouch for searched until two empty searches first; *--agreed-miss 0.4*:
            the fixed cheap confirmation (miss at most 40 %) at every level; *one lattice level more*: fewer rays searched in full. docs/rendering.md weighs these rows and the Qornell box
            for the default's choice.
            """);
        var alternatives = AccuracyBenchmark.Alternatives;
        var measured = alternativeSizes.ToDictionary(size => size, size =>
        {
            progress($"alternatives, {size}x{size}");
            return RandomScene.Kinds.Where(k => k != RandomSceneKind.Deep).SelectMany(kind => AccuracyBenchmark.Measure(kind, size, alternativeSeeds, alternatives)).ToArray();
        });
        var ways = new TextTable("alternatives", ["configuration", .. alternativeSizes.SelectMany(size => new[] { $"{size}x{size}: wrong", "Int/Ray" })]);
        foreach (var c in alternatives)
        {
            var row = new List<string> { c.Name };
            foreach (var size in alternativeSizes)
            {
                var cellsAtSize = measured[size].Where(cell => cell.Configuration == c.Name).ToArray();
                var (wrong, pixels) = (cellsAtSize.Sum(r => r.WrongPixels), cellsAtSize.Sum(r => r.Pixels));
                var intPerRay = (double)cellsAtSize.Sum(r => r.IntersectionsConservative) / cellsAtSize.Sum(r => r.Rays);
                row.Add(Invariant($"{wrong} of {pixels:N0} ({(double)wrong / pixels:P2})"));
                row.Add(Invariant($"{intPerRay:0.0}"));
            }
            ways.Row(row);
        }
        report.Table(ways);

        var byConfiguration = cells.GroupBy(c => c.Configuration).Select(g => (g.Key, Wrong: g.Sum(c => c.WrongPixels), Pixels: g.Sum(c => c.Pixels))).ToArray();
        report.Text("All kinds and sizes together: " + string.Join("; ", byConfiguration.Select(c => Invariant($"{c.Key} {c.Wrong} of {c.Pixels:N0} pixels wrong ({(double)c.Wrong / c.Pixels:P3})"))) + ".");
        return report;
    }

    // Where the default's queries go on scattered scenes of each N in primitives at GrowthSize², beside the other ways to keep the budget.
    private static void Growth(Report report, IReadOnlyList<int> primitives, int seeds, Action<string> progress)
    {
        report.Heading("Where the budget spends its queries as N grows");
        report.Text($"""
            Random scenes of N rectangles of any orientation (`RandomScene.Scattered`, seed 1) at {GrowthSize}x{GrowthSize}: Int/Ray (conservative) of the
            default, split by where it goes (per ray of the render: the lattice's cheap confirmations where neighbours agree; every other
            search and classical test of the passes, rays settled classically included; the budget rounds), beside the same without the budget,
            and the expected and measured wrong pixels (the budget: {Invariant($"{AccuracyBudget.Target * GrowthSize * GrowthSize:0.0}")}), and the Int/Ray of the other ways to keep the budget
            (below: more required misses, the fixed cheap confirmation at every level, one lattice level more). A search that must find a hit
            among N costs about sqrt(N) queries, and so does a confirmation that nothing is closer for a given miss rate: every part grows with N.
            The default sizes each lattice level's cheap confirmation so that the ledger's charge for it, with the rounds it would still need,
            costs least, and the rounds buy the expectation down where a stratum's finds put it, searching the rays a stratum's finds
            put under suspicion together in pooled searches over their (ray, primitive) pairs (docs/rendering.md).
            """);
        var others = AccuracyBenchmark.Alternatives.Skip(1).ToArray();
        var growth = new TextTable("growth", ["N", "default: Int/Ray", "cheap confirmations", "other searches and tests", "budget rounds", "settled",
            "default: expected", "default: wrong", .. others.Select(c => $"{c.Name}: Int/Ray"), "no budget: Int/Ray", "no budget: expected", "no budget: wrong"]);
        var seedOne = new List<(int N, RenderMeasurement First)>();
        foreach (var n in primitives)
        {
            progress($"{n} random rectangles, {GrowthSize}x{GrowthSize}");
            var (scene, reference) = GrowthScene(n, 1);
            var (kept, free) = (RenderMeasurement.Run(scene, new EngineSetup(EngineKind.Analytic), AccuracyBenchmark.Standard[0].Options(GrowthSize, 1), reference),
                RenderMeasurement.Run(scene, new EngineSetup(EngineKind.Analytic), AccuracyBenchmark.Standard[1].Options(GrowthSize, 1), reference));
            seedOne.Add((n, kept));
            var total = kept.Result.Total;
            string PerRay(long intersections) => Invariant($"{(double)intersections / Math.Max(1, total.Rays):0.0}");
            growth.Row([Invariant($"{n:N0}"), Invariant($"{total.PerRayConservative:0.0}"), PerRay(total.CheapIntersections),
                PerRay(total.IntersectionsConservative - total.CheapIntersections - total.RoundIntersections), PerRay(total.RoundIntersections),
                Invariant($"{total.SettledRays:N0}"), Invariant($"{kept.Result.Budget.ExpectedWrongPixels:0.0}"), Invariant($"{kept.Error.DifferentPixels}"),
                .. others.Select(c => Invariant($"{RenderMeasurement.Run(scene, new EngineSetup(EngineKind.Analytic, c.QSearch), c.Options(GrowthSize, 1), reference).Result.Total.PerRayConservative:0.0}")),
                Invariant($"{free.Result.Total.PerRayConservative:0.0}"), Invariant($"{free.Result.Budget.ExpectedWrongPixels:0.0}"), Invariant($"{free.Error.DifferentPixels}")]);
        }
        report.Table(growth);
        SeedSpread(report, seedOne, seeds, progress);
    }

    // The default on seeds 1..seeds of each N: one scene's cost depends on how many of its cheap confirmations happen to find
    // something, since each find charges its whole stratum and the rounds then confirm the rays of it.
    private static void SeedSpread(Report report, IReadOnlyList<(int N, RenderMeasurement First)> seedOne, int seeds, Action<string> progress)
    {
        report.Text($$"""
            The default on seeds 1 to {{seeds}} of each N (same scenes and size): Int/Ray (conservative) by seed, its mean and range, the
            budget rounds' share of it, and the expected and measured wrong pixels summed over the seeds (the budget: {{Invariant($"{AccuracyBudget.Target * GrowthSize * GrowthSize * seeds:0.0}")}}).
            A scene costs more where its cheap confirmations happen to find something: each find raises the charge of its whole
            stratum (every ray of that lattice level on the cheap path), and the rounds then confirm rays of that stratum until
            the charge is within the allowance, in one pooled search per pool where that is cheaper than one search per ray.
            """);
        var table = new TextTable("growth-seeds", ["N", "Int/Ray by seed", "mean", "min", "max", "budget rounds (mean)", "expected", "wrong"]);
        foreach (var (n, first) in seedOne)
        {
            var runs = Enumerable.Range(2, seeds - 1).Select(seed =>
            {
                progress($"{n} random rectangles, {GrowthSize}x{GrowthSize}, seed {seed} of {seeds}");
                var (scene, reference) = GrowthScene(n, (ulong)seed);
                return RenderMeasurement.Run(scene, new EngineSetup(EngineKind.Analytic), AccuracyBenchmark.Standard[0].Options(GrowthSize, 1), reference);
            }).Prepend(first).ToArray(); // seed 1 is the growth table's render
            var perRay = runs.Select(r => r.Result.Total.PerRayConservative).ToArray();
            table.Row([Invariant($"{n:N0}"), string.Join(" ", perRay.Select(x => Invariant($"{x:0.0}"))), Invariant($"{perRay.Average():0.0}"),
                Invariant($"{perRay.Min():0.0}"), Invariant($"{perRay.Max():0.0}"),
                Invariant($"{runs.Average(r => (double)r.Result.Total.RoundIntersections / Math.Max(1, r.Result.Total.Rays)):0.0}"),
                Invariant($"{runs.Sum(r => r.Result.Budget.ExpectedWrongPixels):0.0}"), Invariant($"{runs.Sum(r => r.Error.DifferentPixels)}")]);
        }
        report.Table(table);
    }

    // The growth tables' scene of n scattered rectangles for a seed, and its classical render at their size.
    private static (Scenes.Scene Scene, RenderMeasurement Reference) GrowthScene(int n, ulong seed)
    {
        var scene = RandomScene.Scattered(n, seed);
        return (scene, RenderMeasurement.Reference(scene, RenderOptions.PaperPipeline(GrowthSize, GrowthSize)));
    }

    private static string KindName(RandomSceneKind kind) => kind switch
    {
        RandomSceneKind.Scattered => "scattered, N = 37",
        RandomSceneKind.Ties => "ties, N = 24",
        RandomSceneKind.SharedEdges => "shared edges",
        RandomSceneKind.Deep => "deep, N = 4,000",
        RandomSceneKind.Fractional => "fractional grid, N = 29",
        _ => kind.ToString(),
    };
}
