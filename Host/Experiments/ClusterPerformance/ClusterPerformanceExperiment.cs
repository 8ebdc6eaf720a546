using System.Globalization;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// `bench cluster-performance`: the same fullstate render on local bridges and on a cluster's workers, and the time one bridge
/// request takes on each path, the per-chunk overhead of the cluster; and a large analytic frame by this process alone against
/// the cluster's workers in tiles (docs/cluster-performance.md).
/// </summary>
public static class ClusterPerformanceExperiment
{
    public const string Title = "Cluster against local bridges";

    public static Report Run(ClusterPerformanceSettings settings, Action<string> progress)
    {
        var (scene, size, seed, cluster) = (settings.Scene, settings.Size, settings.Seed, settings.Cluster);
        var options = RenderDefaults.Options(size, size, seed);
        progress($"classical reference of {scene.Name} at {size}x{size}");
        var reference = RenderMeasurement.Reference(scene, options);
        using var local = new BridgePool(settings.Workers);

        progress($"{settings.Requests} single requests on local bridges, then on the cluster");
        var localTrip = ClusterBenchmark.RoundTripMilliseconds(local, settings.Requests);
        var clusterTrip = ClusterBenchmark.RoundTripMilliseconds(cluster, settings.Requests);
        // Local first, then the cluster, each after the round trips started its bridges.
        progress("fullstate render on local bridges");
        var onLocal = RenderMeasurement.Run(scene, new EngineSetup(EngineKind.FullState, new QSearchOptions(), settings.Workers, Pool: local), options, reference);
        progress("fullstate render on the cluster");
        var onCluster = RenderMeasurement.Run(scene, new EngineSetup(EngineKind.FullState, new QSearchOptions(), settings.Workers, Pool: cluster), options, reference);

        var report = new Report(Title);
        report.Text($"Fullstate render of {scene.Name} at {size}x{size}, seed {seed}, `render`'s default pipeline; one run each, local first. "
            + "#Dpix against the classical render (the simulator cannot be seeded, so the two renders differ by chance).");
        var renders = new TextTable("renders", ["where", "bridges", "wall time", "ms per ray", "against local", "#Dpix"]);
        renders.Row(local.Where, N(local.Workers), F(onLocal.WallTime.TotalSeconds, "0.00") + " s", F(onLocal.MillisecondsPerRay, "0.000"), "1.00x", N(onLocal.Error.DifferentPixels));
        renders.Row(cluster.Where, N(cluster.Workers), F(onCluster.WallTime.TotalSeconds, "0.00") + " s", F(onCluster.MillisecondsPerRay, "0.000"),
            F(onCluster.WallTime / onLocal.WallTime, "0.00") + "x", N(onCluster.Error.DifferentPixels));
        report.Table(renders);
        report.Text($"One bridge request at a time (its version; {settings.Requests} requests after a warm-up): local {F(localTrip, "0.00")} ms, cluster {F(clusterTrip, "0.00")} ms; "
            + $"the cluster path's difference per chunk: {F(clusterTrip - localTrip, "+0.00;-0.00")} ms (a difference below a millisecond or two is within the noise of a shared machine).");
        if (settings.FrameSize > 0)
        {
            progress($"analytic frame of {scene.Name} at {settings.FrameSize}x{settings.FrameSize}: this process alone, then the cluster's workers in tiles");
            Frame(report, ClusterFrame.Measure(scene, settings.FrameSize, seed, cluster), scene.Name, seed);
        }
        return report;
    }

    private static void Frame(Report report, ClusterFrame frame, string scene, ulong seed)
    {
        report.Heading("Large frames on the workers");
        report.Text($"An analytic render of {scene} at {frame.Size}x{frame.Size}, seed {seed}, `render`'s default pipeline, without its classical reference: "
            + $"by this process alone, then by the cluster's workers in tiles of {TiledRender.TileSize}x{TiledRender.TileSize} (`render --cluster`), each after a "
            + $"{ClusterFrame.WarmUpSide}x{ClusterFrame.WarmUpSide} warm-up on the same side; one run each. The workers run on the machines the cluster file names: "
            + "workers on this machine share its cores with each other and with the render that sends them tiles.");
        var table = new TextTable("frame", ["where", "wall time", "against this process", "same image bytes"]);
        table.Row("this process alone", F(frame.Local.TotalSeconds, "0.00") + " s", "1.00x", "");
        table.Row(frame.Where, F(frame.OnCluster.TotalSeconds, "0.00") + " s", F(frame.OnCluster / frame.Local, "0.00") + "x", frame.SameImage ? "yes" : "**no**");
        report.Table(table);
        if (frame is { LoadBefore: { } before, LoadAfter: { } after })
            report.Text($"One-minute load average before and after the two frames: {F(before, "0.0")} and {F(after, "0.0")}, on {Environment.ProcessorCount} cores; above the core count other work shared the machine.");
    }

    private static string F(double value, string format) => value.ToString(format, CultureInfo.InvariantCulture);

    private static string N(long value) => value.ToString(CultureInfo.InvariantCulture);
}
