using System.Globalization;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Reports;
using static QuantumRayTracing.Experiments.FullStateBenchmark;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// `bench fullstate-performance`: whole renders on the fullstate engine, the current engine beside the baseline it replaced, each
/// render's time split into bridge calls and simulation, and the simulator-only floor (docs/fullstate-performance.md).
/// </summary>
public static class FullStatePerformanceExperiment
{
    public const string Title = "Performance: whole renders on the fullstate engine";

    public static Report Run(FullStatePerformanceSettings settings, Action<string> progress)
    {
        var rows = new List<Row>();
        foreach (var (name, scene) in settings.Scenes)
            foreach (var size in settings.Sizes)
            {
                // Back to back, so both see the same load on a shared machine.
                Variant[] variants = (long)size * size * new SceneGeometry(scene).Count <= settings.BaselineLimit ? [Variant.Baseline, Variant.Current] : [Variant.Current];
                foreach (var variant in variants)
                {
                    progress($"rendering {name} at {size}x{size} on the {Engine(variant)} fullstate engine");
                    rows.Add(FullStateBenchmark.Run(name, scene, size, variant, settings.Workers, settings.Seed, settings.Pool));
                }
            }

        var report = new Report(Title);
        report.Text($"""
            `render --engine fullstate` with the default pipeline (seed {settings.Seed}, {settings.Pool?.Workers ?? settings.Workers} workers), timed from the first search to the image,
            on the current engine and on the baseline it replaced, rendered back to back:
            """);
        report.Text("""
            - **baseline**: QSearch in lock-step rounds, one bridge call per round and worker, and the oracle and the reflection's S₀ built
              from the standard library's `Controlled Z` on a flag qubit (`MeasureGroverBatchWithControlledZ`), as the engine was first built;
            - **current**: each search's remaining Grover runs planned at once and run in one call (`MeasureGroverSchedules`, stopping at the
              first marked index), and the phase on the all-ones state as a Toffoli ladder into auxiliaries allocated once per search.
            """);
        report.Text("""
            Both run the same algorithm: the same QSearch schedules and counts (Int/Ray differs only by the simulator's unseeded outcomes).
            *Calls* are the bridge requests of the render; *in calls* is the time the host waited for them, summed over the workers. The
            *call floor* is the fixed cost of one call (the QDK compiles the program and its standard library on every call), measured
            before each render as the median of 9 calls of one Grover run over one index; *floor share* = calls × call floor / time in
            calls. The rest of the time in calls is the simulation: divided by the Grover runs it is the cost per run, and divided by
            the workers and the rays it is the *simulator-only floor* per ray, the time a render would take if calls cost nothing and
            the host's own work were free.
            """);
        report.Text("""
            *Load* is the machine's 1-minute load average after the render: on a machine shared with other work the absolute times
            grow with it (the call floor, the same call every time, shows by how much), so compare the two engines by the ratios of
            renders run back to back, below.
            """);
        var renders = new TextTable("renders", ["scene", "size", "engine", "rays", "wall", "ms/ray", "calls", "in calls", "call floor", "floor share", "Grover runs", "simulation ms/run", "simulator-only floor ms/ray", "load"]);
        foreach (var r in rows)
            renders.Row(r.Scene, $"{r.Size}²", Engine(r.Variant), N(r.Rays), F(r.Wall.TotalSeconds, "0.0") + " s", F(r.MillisecondsPerRay, "0.00"), N(r.Calls),
                F(r.CallTime.TotalSeconds, "0.0") + " s", F(r.CallFloorMs, "0") + " ms", F(100 * r.FloorShare, "0") + " %", N(r.GroverRuns), F(r.SimulationMsPerRun, "0.000"),
                F(r.FloorMsPerRay, "0.00"), double.IsNaN(r.LoadAverage) ? "?" : F(r.LoadAverage, "0.0"));
        report.Table(renders);

        var pairs = rows.Where(r => r.Variant == Variant.Current)
            .Select(c => (Current: c, Baseline: rows.FirstOrDefault(b => b.Variant == Variant.Baseline && b.Scene == c.Scene && b.Size == c.Size)))
            .Where(p => p.Baseline is not null).ToArray();
        if (pairs.Length > 0)
        {
            report.Text("Baseline against current, measured back to back (ratios hold better than absolute times on a shared machine):");
            var ratios = new TextTable("ratios", ["scene", "size", "wall: baseline / current", "calls: baseline / current", "simulation ms/run: baseline / current"]);
            foreach (var (c, b) in pairs)
                ratios.Row(c.Scene, $"{c.Size}²", F(b!.Wall / c.Wall, "0.0") + "x", F((double)b.Calls / c.Calls, "0.0") + "x", F(b.SimulationMsPerRun / c.SimulationMsPerRun, "0.0") + "x");
            report.Table(ratios);
        }
        return report;
    }

    private static string Engine(Variant variant) => variant == Variant.Current ? "current" : "baseline";

    private static string F(double value, string format) => value.ToString(format, CultureInfo.InvariantCulture);

    private static string N(long value) => value.ToString("N0", CultureInfo.InvariantCulture);
}
