using QuantumRayTracing.Experiments;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Cluster;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Tests.Cli;
using QuantumRayTracing.Tests.Cluster;
using QuantumRayTracing.Tests.Engines;

namespace QuantumRayTracing.Tests.Experiments;

/// <summary>
/// `--cluster` on the benches whose experiments run Q# engines: a cluster file that is missing or names no worker
/// stops the command with one line and its exit code before any report is written, and on a running cluster each
/// experiment's simulator work goes to the cluster's workers.
/// </summary>
public sealed class BenchClusterOptionTests(OneWorkerCluster worker) : IClassFixture<OneWorkerCluster>, IDisposable
{
    private readonly ScratchDirectory _scratch = new("qrt-bench-cluster-");

    public void Dispose() => _scratch.Dispose();

    // Tiny forms of each bench that takes --cluster, writing their report in the scratch directory.
    private string[] Bench(string name, string cluster) => name switch
    {
        "pareto" => ["bench", "speed-vs-error", "--scene", Path.Combine(RepositoryPaths.Scenes, "qornell-8.json"), "--size", "1", "--cluster", cluster, "-o", _scratch.File("speed-vs-error.md")],
        "grover" => ["bench", "grover-performance", "--sizes", "8", "--batches", "1", "--cluster", cluster, "-o", _scratch.File("grover-performance.md")],
        "soak" => ["bench", "soak", "--short", "--engines", "fullstate", "--scenes", RepositoryPaths.Scenes, "--cluster", cluster, "-o", _scratch.File("soak.md")],
        "noise" => ["bench", "noise", "--parts", "device", "--device-shots", "16", "--cluster", cluster, "-o", _scratch.File("noise.md")],
        _ => throw new ArgumentOutOfRangeException(nameof(name)),
    };

    [Theory]
    [InlineData("pareto")]
    [InlineData("grover")]
    [InlineData("soak")]
    [InlineData("noise")]
    public void AMissingClusterFileIsOneLineAndBadInput(string bench)
    {
        var missing = _scratch.File("no-such-cluster.json");
        var (code, error) = ConsoleCapture.Run(Bench(bench, missing));
        Assert.Equal(ExitCodes.BadInput, code);
        Assert.StartsWith($"error: {missing}: ", error.Trim());
        Assert.DoesNotContain('\n', error.Trim());
        Assert.Equal([], _scratch.FileNames());
    }

    [Fact]
    public void AClusterWithNoWorkerIsOneLineAndAQuantumFailure()
    {
        using var empty = new TestCluster(10);
        using var _ = TestCluster.RefusalIsTheAnswer();
        var (code, error) = ConsoleCapture.Run(Bench("grover", empty.ConfigPath));
        Assert.Equal(ExitCodes.QuantumFailure, code);
        // The error's one line, then the hint every Q# failure gets.
        var lines = error.Trim().Split('\n');
        Assert.Equal(2, lines.Length);
        Assert.StartsWith($"error: {empty.ConfigPath}: no worker", lines[0]);
        Assert.Equal("(run again with --verbose for the details)", lines[1].TrimEnd());
        Assert.Equal([], _scratch.FileNames());
    }

    [Fact]
    public void ParetoRendersItsFullStateRowsOnTheCluster()
    {
        var served = worker.Served;
        var scene = SceneLoader.Load(Path.Combine(RepositoryPaths.Scenes, "qornell-8.json"));
        var report = SpeedVsErrorExperiment.Run(new SpeedVsErrorSettings(scene, 1, 1, 1, worker.Pool), _ => { });

        Assert.True(worker.Served > served, "the full-state renders should have sent their chunks to the worker");
        var rows = report.Table("points").Rows;
        Assert.Equal(SpeedVsErrorExperiment.Engines.Length * SpeedVsErrorExperiment.Configurations(1, 1).Count, rows.Count);
        Assert.Contains(rows, r => r[0] == "fullstate");
    }

    [Fact]
    public void GroverTimesItsAllBridgesColumnOnTheCluster()
    {
        var served = worker.Served;
        var report = GroverPerformanceExperiment.Run(new GroverPerformanceSettings([8], [1, 3], 1, 1, worker.Pool), _ => { });

        // A warm-up call and 9 timed calls (batch 1), then a warm-up and 3 timed calls (batch 3).
        Assert.Equal(14, worker.Served - served);
        var table = report.Table("runs");
        Assert.Equal("fullstate, 1 cluster bridge: ms/run", table.Header[4]);
        Assert.Equal([["8", "2", "1"], ["8", "2", "3"]], table.Rows.Select(r => r[..3]));
    }

    [Fact]
    public void SoakRendersItsSimulatorRowsOnTheCluster()
    {
        var served = worker.Served;
        var settings = SoakSettings.Short(1) with { Engines = [EngineKind.FullState, EngineKind.Gate], Pool = worker.Pool };
        var result = SoakExperiment.Run([Path.Combine(RepositoryPaths.Scenes, "qornell-8.json")], settings);

        Assert.All(result.Rows, r => Assert.Equal(SoakStatus.Ok, r.Status));
        Assert.True(worker.Served > served, "the fullstate and gate renders should have sent their chunks to the worker");
        Assert.Equal(2, result.Report.Table("soak").Rows.Count);
    }

    [Fact]
    public void NoiseRunsItsDeviceExperimentOnTheCluster()
    {
        var served = worker.Served;
        var settings = new NoiseBenchSettings(new HashSet<string> { "device" }, 100, 16, [], 8, 0, [], 1, worker.Pool);
        var (report, machine, _) = NoiseExperiment.Run(settings, _ => { });

        Assert.True(worker.Served > served, "the device experiment's gate-level runs should have gone to the worker");
        var rows = report.Table("device-histograms").Rows;
        Assert.Equal(NoiseBenchSettings.DeviceRates.Length, rows.Count);
        // Each row: the rate, the share of each of the 4 indices (16 shots), the distance from uniform.
        Assert.All(rows, r => Assert.Equal(1.0, r[1..5].Sum(share => double.Parse(share, System.Globalization.CultureInfo.InvariantCulture)), 2));
        Assert.Contains("qsharp-lang", machine, StringComparison.Ordinal);
    }
}

/// <summary>One worker with one bridge in a localhost cluster, and a client's pool over it, shared by a test class.</summary>
public sealed class OneWorkerCluster : IDisposable
{
    private readonly WorkerBridges _bridges = new(1);
    private readonly TestCluster _cluster;

    public OneWorkerCluster()
    {
        _cluster = new TestCluster(120, _bridges);
        Pool = ClusterBridges.Start(_cluster.ConfigPath, 1);
    }

    public BridgePool Pool { get; }

    /// <summary>Chunks the worker has finished so far.</summary>
    public long Served => _cluster.Served(0);

    public void Dispose()
    {
        Pool.Dispose();
        _cluster.Dispose();
        _bridges.Dispose();
    }
}
