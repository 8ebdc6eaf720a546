using System.Globalization;
using System.Text.RegularExpressions;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Output;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Reports;
using static System.FormattableString;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// `bench scale`: wall time and peak memory of `render` against the pixel count, per engine, each render in a process of
/// its own (docs/scale.md); a render the memory guard refuses is listed with its forecast.
/// </summary>
public static partial class ScaleExperiment
{
    public const string Title = "Scale: time and memory against image size";

    /// <summary>One render: its engine and size, and what it took (null figures: refused, with the reason).</summary>
    public sealed record Row(EngineKind Engine, int Size, double? RenderSeconds, double? ReferenceSeconds, long PeakBytes, double? PerRay, string? Forecast, string? ForecastTime, string? Refusal)
    {
        public long Pixels => (long)Size * Size;

        /// <summary>The render's classical tests (#C_Int), for its tests per second of render wall time.</summary>
        public long? ClassicalTests { get; init; }

        /// <summary>
        /// #C_Int per second of render wall time, on the engines whose every search is classical (brute force: ray–primitive
        /// tests, the lattice's neighbour tests among them; the BVH: node and primitive tests); null on the others.
        /// </summary>
        public double? TestsPerSecond => Engine is EngineKind.Classical or EngineKind.Bvh && RenderSeconds is { } t && ClassicalTests is { } n ? n / t : null;
    }

    public static Report Run(ScaleSettings settings, Action<string> progress)
    {
        var scratch = Directory.CreateTempSubdirectory("qrt-scale-");
        try
        {
            var loadBefore = MachineLoad.OneMinute();
            var rows = new List<Row>();
            foreach (var size in settings.Sizes)
                foreach (var engine in settings.Engines)
                {
                    progress(Invariant($"scale: {engine.Name} at {size}x{size}"));
                    rows.Add(Measure(settings, engine, size, scratch.FullName));
                }
            return Write(settings, rows, (loadBefore, MachineLoad.OneMinute()));
        }
        finally
        {
            scratch.Delete(recursive: true);
        }
    }

    private static Row Measure(ScaleSettings settings, EngineKind engine, int size, string scratch)
    {
        var (image, json) = (Path.Combine(scratch, "render.png"), Path.Combine(scratch, "render.json"));
        foreach (var file in Directory.EnumerateFiles(scratch)) File.Delete(file);
        var run = RenderProcess.Run(["render", settings.SceneFile, "--engine", engine.Name, "--size", Invariant($"{size}"),
            "--seed", Invariant($"{settings.Seed}"), "--reference-samples", "0", "-o", image], json);
        var match = ForecastLine().Match(run.Output);
        var (forecast, forecastTime) = match.Success ? (match.Groups[1].Value, match.Groups[2].Value + " s") : (null, null);
        if (run.Figures is not { } figures)
        {
            // The memory guard's refusal is a result; any other failure ends the experiment.
            if (!run.Error.Contains("--max-memory", StringComparison.Ordinal)) throw new InvalidOperationException($"render {engine.Name} {size}x{size} failed (exit {run.ExitCode}): {run.Error}");
            return new Row(engine, size, null, null, run.PeakBytes, null, forecast, forecastTime, run.Error);
        }
        double Seconds(string field) => figures[field]!.GetValue<double>();
        return new Row(engine, size, Seconds("renderTime"), Seconds("referenceTime"), run.PeakBytes,
            figures["total"]!["perRayConservative"]!.GetValue<double>(), forecast, forecastTime, null)
        {
            ClassicalTests = figures["total"]!["cost"]!["classicalTests"]!.GetValue<long>(),
        };
    }

    [GeneratedRegex(@"forecast: peak memory about ([0-9.]+ [MG]B) .*?at most about ([0-9]+) s")]
    private static partial Regex ForecastLine();

    private static Report Write(ScaleSettings settings, IReadOnlyList<Row> rows, (double? Before, double? After) load)
    {
        var report = new Report(Title);
        report.Text(Invariant($"""
            `render {Path.GetFileName(settings.SceneFile)} --engine E --size S --seed {settings.Seed} --reference-samples 0`, each in a process of its own: the
            render on the engine, then the classical reference it is compared with (same as every `render`). *Render* and *reference* are their wall
            times as the render's JSON gives them; *peak memory* is the process's peak resident memory (Linux VmHWM, read every
            {RenderProcess.PollInterval.TotalMilliseconds:F0} ms), over both renders. From 1024x1024 pixels both renders are tiled (tiles of {TiledRender.TileSize}x{TiledRender.TileSize}
            and a border, [rendering.md](rendering.md#tiles)), so memory is the images' bytes and the work of the tiles rendered at once (two on these engines); the tiles' border rays are in Int/Ray.
            From 1024x1024 pixels `render` also forecasts the run first and refuses one whose
            forecast memory exceeds what the machine has available ([rendering.md](rendering.md#large-renders-forecast-memory-guard-and-progress)): such rows give the forecast and no times. The forecast time covers the render and its reference: compare it with their sum.
            Int/Ray is conservative (docs/conventions.md; the BVH's counts node and primitive tests and its build). *Tests/s* is the render's #C_Int
            per second of its wall time (planning, every pass and shading included), on the engines whose every search is classical: brute force's
            ray–primitive tests (the lattice's neighbour tests among them) and the BVH's node and primitive tests.
            """));
        if (load is { Before: { } before, After: { } after })
            report.Text(Invariant($"One-minute load average when the run started and ended: {before:F1} and {after:F1}, on {Environment.ProcessorCount} cores. Above the core count other work shared the machine, and the times are upper bounds; memory does not depend on it."));
        var table = new TextTable("scale", ["engine", "size", "pixels", "render", "reference", "peak memory", "bytes per pixel", "forecast memory", "forecast time", "Int/Ray", "tests/s"]);
        foreach (var r in rows)
            table.Row(r.Engine.Name, Invariant($"{r.Size}x{r.Size}"), Invariant($"{r.Pixels:N0}"),
                r.RenderSeconds is { } t ? Invariant($"{t:F2} s") : "refused", r.ReferenceSeconds is { } rt ? Invariant($"{rt:F2} s") : "",
                r.Refusal is null ? RenderForecast.Bytes(r.PeakBytes) : "", r.Refusal is null ? Invariant($"{r.PeakBytes / (double)r.Pixels:N0}") : "",
                r.Forecast ?? "", r.ForecastTime ?? "", r.PerRay is { } p ? Invariant($"{p:F2}") : "",
                r.TestsPerSecond is { } rate ? Invariant($"{rate / 1e6:F0} M") : "");
        report.Table(table.AlignRight(2, 3, 4, 5, 6, 7, 8, 9, 10));
        if (rows.Any(r => r.Refusal is not null))
            report.Text(string.Join("\n", rows.Where(r => r.Refusal is not null).Select(r => Invariant($"- {r.Engine.Name} at {r.Size}x{r.Size}: `{r.Refusal}`"))));

        var measured = rows.Where(r => r.RenderSeconds is not null).ToArray();
        PlotSeries By(EngineKind engine, Func<Row, double> value) =>
            new(engine.Name, [.. measured.Where(r => r.Engine == engine).Select(r => ((double)r.Pixels, value(r)))]);
        if (measured.Select(r => r.Size).Distinct().Count() > 1)
        {
            report.Plot("time", new PlotSpec("Render time against pixels", "pixels", "render wall time (s)", AxisScale.Log10, AxisScale.Log10,
                [.. settings.Engines.Select(e => By(e, r => r.RenderSeconds!.Value))]), "Wall time of the render alone (not its reference) against the pixel count");
            report.Plot("memory", new PlotSpec("Peak memory against pixels", "pixels", "peak resident memory (MB)", AxisScale.Log10, AxisScale.Log10,
                [.. settings.Engines.Select(e => By(e, r => r.PeakBytes / (double)(1 << 20)))]), "Peak resident memory of the process (render and classical reference) against the pixel count");
        }
        return report;
    }
}
