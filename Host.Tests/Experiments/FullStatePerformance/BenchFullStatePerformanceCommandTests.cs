using QuantumRayTracing.Experiments;
using QuantumRayTracing.Tests.Cli;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Tests.Cluster;

namespace QuantumRayTracing.Tests.Experiments;

/// <summary>`bench fullstate-performance` given a `--cluster` it cannot use stops with one line and the cluster's exit code, before any work and without a report.</summary>
public sealed class BenchFullStatePerformanceCommandTests : IDisposable
{
    private readonly ScratchDirectory _scratch = new("qrt-bench-cluster-option");

    public void Dispose() => _scratch.Dispose();

    private (int Code, string Error) Bench(string cluster) => ConsoleCapture.Run("bench", "fullstate-performance", "--scenes", RepositoryPaths.Scenes, "--scene-names", "qornell-8",
        "--sizes", "2", "--workers", "1", "--cluster", cluster, "-o", _scratch.File("fullstate-performance.md"));

    [Fact]
    public void AMissingClusterFileIsBadInput()
    {
        var missing = _scratch.File("no-such-cluster.json");
        var (code, error) = Bench(missing);
        Assert.Equal(ExitCodes.BadInput, code);
        Assert.StartsWith($"error: {missing}: cannot read the cluster file", error.Trim());
        Assert.Single(error.Trim().Split('\n'));
        Assert.Equal([], _scratch.FileNames());
    }

    [Fact]
    public void AClusterWithoutWorkersIsAQuantumFailure()
    {
        using var cluster = new TestCluster(5); // the file only: no worker started
        var (code, error) = Bench(cluster.ConfigPath);
        Assert.Equal(ExitCodes.QuantumFailure, code);
        var lines = error.Trim().Split('\n');
        Assert.StartsWith($"error: {cluster.ConfigPath}: no worker of cluster", lines[0]);
        // One line of error; only the hint where to find the details may follow.
        Assert.All(lines.Skip(1), line => Assert.StartsWith("(run again with --verbose", line));
        Assert.Equal([], _scratch.FileNames());
    }
}
