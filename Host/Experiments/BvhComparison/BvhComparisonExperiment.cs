using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Output;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Generation;
using QuantumRayTracing.Search.Bvh;
using static System.FormattableString;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// `bench bvh-comparison`: Int/Ray against N for brute force, a BVH (its walks and its build, charged once per frame as
/// for a dynamic scene) and the quantum pipeline, on the scenes the ray tracing paper uses and on random ones
/// (docs/bvh-comparison.md). The paper leaves spatial structures out on purpose (its sec. 2); this is the comparison.
/// </summary>
public static class BvhComparisonExperiment
{
    public const string Title = "Brute force, a BVH and quantum search: Int/Ray against N";

    /// <summary>One measured scene: its primitives, rays, and each engine's whole-frame Int/Ray.</summary>
    public sealed record Row(string Scene, int Primitives, long Rays, double BruteForce, double BvhWalks, double BvhBuild, double Quantum, int Nodes, long BuildWork)
    {
        public double Bvh => BvhWalks + BvhBuild;
    }

    public static Report Run(BvhComparisonSettings settings, Action<string> progress)
    {
        var rows = Scenes(settings).Select(s =>
        {
            progress($"bvh-comparison: {s.Name}");
            return Measure(s.Name, s.Scene, settings);
        }).ToArray();
        return Write(settings, rows);
    }

    /// <summary>The measured scenes in order: the Qornell box by N, Depth Complexity, scattered random rectangles.</summary>
    public static IEnumerable<(string Name, Scene Scene)> Scenes(BvhComparisonSettings settings)
    {
        foreach (var n in settings.QornellSizes) yield return ($"Qornell box {n}", SceneLoader.Parse(QornellBox.Build(n).ToJson(), $"qornell-{n}"));
        foreach (var n in DepthComplexityScene.Sizes) yield return ($"Depth Complexity {n}", SceneLoader.Parse(DepthComplexityScene.Build(n).ToJson(), $"depth-complexity-{n}"));
        foreach (var n in settings.RandomSizes) yield return ($"{n} random rectangles", RandomScene.Scattered(n, settings.Seed));
    }

    /// <summary>
    /// One scene: brute force and the BVH on the paper's plain pipeline (one certain search per ray), the quantum
    /// pipeline as `render` runs it on the analytic engine; conservative counts.
    /// </summary>
    public static Row Measure(string name, Scene scene, BvhComparisonSettings settings)
    {
        var plain = RenderOptions.PaperPipeline(settings.Size, settings.Size, settings.Seed);
        var brute = Renderer.Render(scene, new EngineSetup(EngineKind.Classical), plain).Total;
        var bvh = Renderer.Render(scene, new EngineSetup(EngineKind.Bvh), plain).Total;
        var quantum = Renderer.Render(scene, new EngineSetup(EngineKind.Analytic), RenderDefaults.Options(settings.Size, settings.Size, settings.Seed)).Total;
        var hierarchy = BoundingVolumeHierarchy.Build(new SceneGeometry(scene));
        var build = (double)hierarchy.BuildWork / bvh.Rays;
        return new Row(name, scene.Primitives.Count, bvh.Rays, brute.PerRayConservative, bvh.PerRayConservative - build, build,
            quantum.PerRayConservative, hierarchy.Nodes.Count, hierarchy.BuildWork);
    }

    private static Report Write(BvhComparisonSettings settings, IReadOnlyList<Row> rows)
    {
        var report = new Report(Title);
        report.Text(Invariant($"""
            Whole frames at {settings.Size}x{settings.Size} pixels, seed {settings.Seed}: primary, mirror and shadow rays. Int/Ray = (#Eval + #C_Int) / #Rays,
            conservative count (a Grover run with r ≥ 1 iterations costs r + 1 queries; docs/conventions.md).

            - **Brute force** (`--engine classical`): every ray tests every primitive, N per ray.
            - **BVH** (`--engine bvh`): a bounding-volume hierarchy built with the surface area heuristic (16 centroid bins per axis, leaves of
              at most {BoundingVolumeHierarchy.MaxLeafSize}). A walk counts one test per node box it tests and one per primitive it tests, the same unit as #C_Int. The build
              is counted once per frame, as for a dynamic scene: one unit per primitive box read (binning on three axes and the partition,
              about 4 N log2 N), spread over the frame's rays in the *build* column. Its answers are brute force's, so its image is too.
            - **Quantum**: `render`'s default pipeline (lattice, cheap confirmations, the accuracy budget) on the analytic engine.
              Its Int/Ray counts oracle queries and classical tests; the oracle's own gates grow with N (it loads every primitive),
              which Int/Ray does not show (docs/frame-sweep.md prices them). Its budget rounds may search many rays' (ray, primitive)
              pairs at once, each query loading a ray beside a primitive (docs/conventions.md, pooled searches).

            Brute force and the BVH run the paper's plain pipeline (one search per ray); their answers are certain, so the lattice has nothing to add.
            """));
        var table = new TextTable("bvh-comparison", ["scene", "N", "rays", "brute force", "BVH walks", "BVH build", "BVH total", "quantum", "BVH nodes", "build work"]);
        foreach (var r in rows)
            table.Row(r.Scene, Invariant($"{r.Primitives}"), Invariant($"{r.Rays:N0}"), Invariant($"{r.BruteForce:F2}"), Invariant($"{r.BvhWalks:F2}"),
                Invariant($"{r.BvhBuild:F2}"), Invariant($"{r.Bvh:F2}"), Invariant($"{r.Quantum:F2}"), Invariant($"{r.Nodes}"), Invariant($"{r.BuildWork:N0}"));
        report.Table(table.AlignRight(1, 2, 3, 4, 5, 6, 7, 8, 9));

        var qornell = rows.Where(r => r.Scene.StartsWith("Qornell", StringComparison.Ordinal)).ToArray();
        var random = rows.Where(r => r.Scene.EndsWith("random rectangles", StringComparison.Ordinal)).ToArray();
        PlotSeries Series(string label, IEnumerable<Row> of, Func<Row, double> value) => new(label, [.. of.Select(r => ((double)r.Primitives, value(r)))]);
        if (qornell.Length > 1)
            report.Plot("qornell", new PlotSpec("Int/Ray against N, Qornell box", "primitives N", "Int/Ray (conservative)", AxisScale.Log10, AxisScale.Log10,
                [Series("brute force", qornell, r => r.BruteForce), Series("BVH (walks + build)", qornell, r => r.Bvh), Series("quantum (render's default)", qornell, r => r.Quantum)]),
                "Int/Ray against N on the Qornell box: the primitives added as N grows stand behind the camera, so the BVH culls them with a box test or two");
        if (random.Length > 1)
            report.Plot("random", new PlotSpec("Int/Ray against N, scattered random rectangles", "primitives N", "Int/Ray (conservative)", AxisScale.Log10, AxisScale.Log10,
                [Series("brute force", random, r => r.BruteForce), Series("BVH (walks + build)", random, r => r.Bvh), Series("quantum (render's default)", random, r => r.Quantum)]),
                "Int/Ray against N on scattered random rectangles, every one of them in view");

        report.Heading("Reading it");
        report.Text(Reading(rows));
        return report;
    }

    // What the table says, from the measured rows: where the BVH and quantum stand against each other at the largest N.
    private static string Reading(IReadOnlyList<Row> rows)
    {
        var lines = rows.Where(r => r.Primitives >= 512).Select(r => Invariant(
            $"- {r.Scene}: the BVH costs {r.Bvh:F1} Int/Ray ({r.BvhBuild:F1} of it the build), quantum {r.Quantum:F1}, brute force {r.BruteForce:F0}; quantum / BVH = {r.Quantum / r.Bvh:F2}."));
        lines = lines.Concat(rows.Where(r => r.Bvh > r.BruteForce).Select(r => Invariant(
            $"- {r.Scene}: the BVH costs more than brute force ({r.Bvh:F2} against {r.BruteForce:F0}): with so few primitives its box tests are overhead.")));
        return lines.Any()
            ? "Measured in this run (counts, not wall time; a count is the same on any machine):\n\n" + string.Join("\n", lines)
            : "No scene of this run has 512 primitives or more.";
    }
}
