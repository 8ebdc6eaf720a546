using QuantumRayTracing.Experiments;
using QuantumRayTracing.Cluster;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Tests.Cluster;
using QuantumRayTracing.Tests.Engines;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Experiments;

/// <summary>`bench cluster-performance`'s experiment against a one-worker cluster in this process: local bridges, then the cluster's, each row naming where it ran.</summary>
public sealed class ClusterPerformanceExperimentTests
{
    [Fact]
    public void RendersLocallyAndOnTheClustersWorker()
    {
        using var bridges = new WorkerBridges(1);
        using var cluster = new TestCluster(120, bridges);
        using var pool = ClusterBridges.Start(cluster.ConfigPath, 1);
        var report = ClusterPerformanceExperiment.Run(new ClusterPerformanceSettings(Load("qornell-8.json"), 2, 3, 1, 1, pool), _ => { });

        var renders = report.Table("renders");
        Assert.Equal("this machine, 1 local bridge", renders.Rows[0][0]);
        Assert.StartsWith("cluster '", renders.Rows[1][0]);
        // The cluster's render and its timed requests went to the worker: 3 requests and a warm-up at least.
        Assert.True(cluster.Served(0) >= 4, $"the worker served {cluster.Served(0)} chunks");
        Assert.Contains("3 requests after a warm-up", report.Blocks.OfType<ReportText>().Last().Markdown);
    }
}
