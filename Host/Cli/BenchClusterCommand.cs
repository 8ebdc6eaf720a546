using System.CommandLine;
using System.Globalization;
using System.Text;
using QuantumRayTracing.Benchmarks;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Cluster;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Cli;

/// <summary>
/// `bench cluster`: the same fullstate render on local bridges and on a cluster's workers, and the time one
/// bridge request takes on each path (the per-chunk overhead of the cluster).
/// </summary>
public sealed class BenchClusterCommand : Command
{
    private readonly BenchReportOptions _report = new("qrt bench cluster", "docs/cluster-performance.md");

    private readonly Option<FileInfo> _cluster = new("--cluster")
    {
        Description = "The cluster file of the running workers (docs/cluster.md). Default: none; the benchmark needs one.",
        HelpName = "file",
        Required = true,
    };

    private readonly Option<int> _size = new("--size")
    {
        Description = "Side of the square render of the Qornell box with 64 primitives, in pixels.",
        DefaultValueFactory = _ => 32,
    };

    private readonly Option<int> _requests = new("--requests")
    {
        Description = "Bridge requests timed one at a time on each path.",
        DefaultValueFactory = _ => 200,
    };

    public BenchClusterCommand() : base("cluster", "A fullstate render and single bridge requests on local bridges against a cluster's workers.")
    {
        Options.Add(_cluster);
        Options.Add(_size);
        Options.Add(_requests);
        _report.AddTo(this);
        _size.Between(1, 1024);
        _requests.Between(1, 100_000);
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var report = _report.Report(parse);
        var scene = _report.Load(parse, "qornell-64");
        var (size, workers, seed) = (parse.GetValue(_size), parse.GetValue(_report.Workers), parse.GetValue(_report.Seed));
        var options = RenderDefaults.Options(size, size, seed);
        var reference = RenderMeasurement.Reference(scene, options);
        using var cluster = ClusterBridges.Start(parse.GetValue(_cluster)!.FullName, workers);
        using var local = new BridgePool(workers);

        var requests = parse.GetValue(_requests);
        var localTrip = ClusterBenchmark.RoundTripMilliseconds(local, requests);
        var clusterTrip = ClusterBenchmark.RoundTripMilliseconds(cluster, requests);
        // Local first, then the cluster, each after the round trips started its bridges.
        var onLocal = RenderMeasurement.Run(scene, EngineKind.FullState, options, new QSearchOptions(), seed, workers, reference, pool: local);
        var onCluster = RenderMeasurement.Run(scene, EngineKind.FullState, options, new QSearchOptions(), seed, workers, reference, pool: cluster);

        string F(double x, string format) => x.ToString(format, CultureInfo.InvariantCulture);
        var text = new StringBuilder();
        text.AppendLine($"# Cluster against local bridges");
        text.AppendLine();
        text.AppendLine($"Fullstate render of {scene.Name} at {size}x{size}, seed {seed}, `render`'s default pipeline; one run each, local first. "
            + "#Dpix against the classical render (the simulator cannot be seeded, so the two renders differ by chance).");
        text.AppendLine();
        text.AppendLine("| where | bridges | wall time | ms per ray | against local | #Dpix |");
        text.AppendLine("|---|---|---|---|---|---|");
        text.AppendLine($"| {local.Where} | {local.Workers} | {F(onLocal.WallTime.TotalSeconds, "0.00")} s | {F(onLocal.MillisecondsPerRay, "0.000")} | 1.00x | {onLocal.Error.DifferentPixels} |");
        text.AppendLine($"| {cluster.Where} | {cluster.Workers} | {F(onCluster.WallTime.TotalSeconds, "0.00")} s | {F(onCluster.MillisecondsPerRay, "0.000")} | {F(onCluster.WallTime / onLocal.WallTime, "0.00")}x | {onCluster.Error.DifferentPixels} |");
        text.AppendLine();
        text.AppendLine($"One bridge request at a time (its version; {requests} requests after a warm-up): local {F(localTrip, "0.00")} ms, cluster {F(clusterTrip, "0.00")} ms; "
            + $"the cluster path's difference per chunk: {F(clusterTrip - localTrip, "+0.00;-0.00")} ms (a difference below a millisecond or two is within the noise of a shared machine).");
        BenchReportOptions.Publish(report, text);
        return 0;
    }
}
