using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Reports;
using static System.FormattableString;

namespace QuantumRayTracing.Experiments;

/// <summary>`bench grover-performance`: wall time per Grover run on the full-state simulator (one bridge and all of them) and the analytic engine (docs/grover-performance.md).</summary>
public static class GroverPerformanceExperiment
{
    public const string Title = "Performance: Grover runs per engine";

    public static Report Run(GroverPerformanceSettings settings, Action<string> progress)
    {
        var random = new SeededRandom(settings.Seed);
        var rows = new List<GroverBenchmark.Row>();
        using (var single = new FullStateEngine(new BridgePool(1)))
        using (var parallel = new FullStateEngine(settings.Pool ?? new BridgePool(settings.Workers), ownsPool: settings.Pool is null))
        {
            var analytic = new AnalyticEngine(random.Fork(RandomStreams.Engine));
            var cases = settings.Sizes.SelectMany(n => settings.Batches.Select(b => (Count: n, Batch: b))).ToArray();
            foreach (var (count, batch) in cases)
            {
                progress($"N = {count}, batch {batch} ({rows.Count + 1}/{cases.Length})");
                var requests = GroverBenchmark.Requests(count, batch, random);
                var repeats = GroverBenchmark.Repeats(batch);
                var oneWorker = GroverBenchmark.MillisecondsPerRun(single, requests, repeats);
                var allWorkers = GroverBenchmark.MillisecondsPerRun(parallel, requests, repeats);
                var analyticRequests = Enumerable.Range(0, Math.Max(1, 100_000 / batch)).SelectMany(_ => requests).ToArray();
                var analyticMicros = 1000 * GroverBenchmark.MillisecondsPerRun(analytic, analyticRequests, 5);
                rows.Add(new(count, GroverBenchmark.OptimalIterations(count), batch, oneWorker, allWorkers, analyticMicros));
            }
        }

        static string F(double v) => v.ToString(v >= 100 ? "0" : v >= 10 ? "0.0" : "0.000", System.Globalization.CultureInfo.InvariantCulture);
        var report = new Report(Title);
        report.Text("""
            Wall time per Grover run (prepare the uniform superposition over N indices, r = floor(π/4·sqrt N) iterations with one marked index, measure)
            on each engine, for batches of 1, 100 and 1000 requests per engine call. The batch of 1 shows the fixed cost of one call through the
            Node bridge (the QDK compiles the program on every call); large batches show the amortised cost of the simulation itself.
            `fullstate` is the Q# operation `MeasureGroverBatch` on the QDK full-state simulator; `analytic` samples the exact outcome
            distribution in C#. Each figure is the median of 9 (batch 1), 3 (batch 100) or 1 (batch 1000) timed calls after a warm-up call.
            """);
        var all = settings.Pool is { } pool ? $"{pool.Workers} cluster bridge{(pool.Workers == 1 ? "" : "s")}" : $"{settings.Workers} workers";
        var table = new TextTable("runs", ["N", "r", "batch", "fullstate, 1 worker: ms/run", $"fullstate, {all}: ms/run", "fullstate, 1 worker: ms/call", "analytic: µs/run", "fullstate / analytic"]);
        foreach (var r in rows)
            table.Row(Invariant($"{r.Count}"), Invariant($"{r.Iterations}"), Invariant($"{r.Batch}"), F(r.FullStateOneWorkerMs), F(r.FullStateAllWorkersMs),
                F(r.FullStateOneWorkerMs * r.Batch), F(r.AnalyticMicroseconds), F(r.FullStateOneWorkerMs * 1000 / r.AnalyticMicroseconds) + "x");
        report.Table(table);
        report.Text("Whole renders on the fullstate engine, with their calls, simulation and simulator-only floor: [fullstate-performance.md](fullstate-performance.md) (`qrt bench fullstate-performance`).");
        return report;
    }
}
