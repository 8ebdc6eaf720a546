using System.Globalization;
using System.Text.Json.Nodes;
using QuantumRayTracing.Experiments;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Cluster;
using QuantumRayTracing.Output;
using QuantumRayTracing.Tests.BadInput;
using QuantumRayTracing.Tests.Cluster;
using QuantumRayTracing.Tests.Engines;

namespace QuantumRayTracing.Tests.Cli;

/// <summary>`estimate` and `estimate oracle-sweep` through <see cref="CommandLine.Run"/>: exit codes and the report file.</summary>
public sealed class EstimateCommandTests(EstimateCommandTests.PricedFrames frames) : IDisposable, IClassFixture<EstimateCommandTests.PricedFrames>
{
    private static readonly string Scene = Path.Combine(RepositoryPaths.Scenes, "qornell-8.json");

    private readonly ScratchDirectory _scratch = new("qrt-estimate-");

    public void Dispose() => _scratch.Dispose();

    /// <summary>
    /// The same 1x1 frame (both passes make Grover runs; a 2x2 frame prices twice the estimator jobs) priced on every
    /// default model for 2 QPUs twice, once here writing its table as Markdown and once on a two-worker cluster writing
    /// it as CSV, each with its --json record: the tests below read what they check from these two runs.
    /// </summary>
    public sealed class PricedFrames : IDisposable
    {
        private readonly ScratchDirectory _scratch = new("qrt-estimate-frames-");
        private readonly Lazy<Runs> _runs;

        public PricedFrames() => _runs = new(() =>
        {
            string[] frame = ["estimate", "--frame", Scene, "--size", "1", "--qpus", "2", "--workers", "1"];
            var (markdown, csv) = (Path.ChangeExtension(_scratch.File("frame"), "md"), _scratch.File("frame.csv"));
            var (local, onCluster) = (_scratch.File("local.json"), _scratch.File("cluster.json"));
            var localCode = ConsoleCapture.Run([.. frame, "-o", markdown, "--json", local]).Code;
            using var first = new WorkerBridges(1);
            using var second = new WorkerBridges(1);
            using var cluster = new TestCluster(120, first, second);
            var clusterCode = ConsoleCapture.Run([.. frame, "--cluster", cluster.ConfigPath, "--format", "csv", "-o", csv, "--json", onCluster]).Code;
            return new Runs(localCode, clusterCode, (cluster.Served(0), cluster.Served(1)), File.ReadAllLines(markdown), File.ReadAllLines(csv),
                JsonNode.Parse(File.ReadAllText(local))!, JsonNode.Parse(File.ReadAllText(onCluster))!);
        });

        public Runs Value => _runs.Value;

        public void Dispose() => _scratch.Dispose();
    }

    /// <summary>Exit codes, the jobs each cluster worker served, the files written and the JSON records of the two runs.</summary>
    public sealed record Runs(int LocalCode, int ClusterCode, (long First, long Second) Served, string[] Markdown, string[] Csv, JsonNode Local, JsonNode OnCluster);

    [Fact]
    public void EstimatesOnePixelsRay()
    {
        var outcome = Outcome.Of("estimate", Scene, "--pixel", "3,4", "--size", "8", "--no-circuit", "--format", "csv", "--workers", "1");
        Assert.True(outcome.Code == 0, outcome.Error);
        Assert.Empty(outcome.Error);
    }

    [Fact]
    public void EstimatesAPooledQueryBesideTheRaysOracle()
    {
        // Two pools of camera rays on qornell-8: a query reads every ray's rows, so it costs more CCZ than one ray's oracle,
        // and a pool of 4 more than one of 2.
        long Ccz(int rays, int column)
        {
            var outcome = Outcome.Of("estimate", Scene, "--pooled", rays.ToString(CultureInfo.InvariantCulture), "--size", "8", "--no-circuit", "--format", "csv",
                "--models", "qubit_gate_ns_e3", "--workers", "1");
            Assert.True(outcome.Code == 0, outcome.Error);
            var lines = outcome.Output.Split('\n', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries);
            Assert.Equal("measure,oracle,pooled query,Grover iteration,pooled iteration", lines.First(l => l.StartsWith("measure,", StringComparison.Ordinal)));
            return long.Parse(lines.First(l => l.StartsWith("CCZ,", StringComparison.Ordinal)).Split(',')[column], CultureInfo.InvariantCulture);
        }
        var (oracle, two, four) = (Ccz(2, 1), Ccz(2, 2), Ccz(4, 2));
        Assert.True(oracle < two && two < four, $"CCZ: oracle {oracle}, pooled query of 2 rays {two}, of 4 rays {four}");
    }

    [Fact]
    public void PoolLargerThanTheImageIsBadInput() =>
        Outcome.Of("estimate", Scene, "--pooled", "65", "--size", "8", "--workers", "1").AssertBadInput("--pooled", "a pool of 65 rays, but a 8x8 image casts 64 camera rays");

    [Theory]
    [InlineData("8,0")]  // outside the 8x8 image: bad input
    [InlineData("0,8")]
    public void PixelOutsideTheImageIsBadInput(string pixel) =>
        Outcome.Of("estimate", Scene, "--pixel", pixel, "--size", "8", "--workers", "1").AssertBadInput($"--pixel {pixel}", "is outside the 8x8 image");

    [Theory]
    [InlineData("--pixel", "choose the ray two ways", "--pixel", "1,2", "--worst-case")]
    [InlineData("--pixel", "expected X,Y (two non-negative integers), got '1'", "--pixel", "1")]
    [InlineData("--pixel", "expected X,Y (two non-negative integers), got '-1,2'", "--pixel", "-1,2")]
    [InlineData("--oracle", "unknown construction 'smallest'", "--oracle", "smallest")]
    [InlineData("--models", "the floquet_code needs a Majorana model", "--models", "qubit_gate_ns_e3:floquet_code")]
    [InlineData("--models", "unknown qubit model 'qubit_gate_xx'", "--models", "qubit_gate_xx")]
    [InlineData("--iterations", "must be between 0 and 100000", "--iterations", "-1")]
    [InlineData("--iterations", "Cannot parse argument 'many'", "--iterations", "many")]
    [InlineData("--format", "'foo' is not one of table, md, csv", "--format", "foo")]
    [InlineData("--pooled", "must be at least 1, got 0", "--pooled", "0")]
    public void UsageErrors(string option, string problem, params string[] options) =>
        Outcome.Of(["estimate", Scene, .. options]).AssertUsageError(option, problem);

    [Theory]
    [InlineData("--error-budget", "must lie strictly between 0 and 1, got 0", "--error-budget", "0")]
    [InlineData("--error-budget", "must lie strictly between 0 and 1, got 1", "--error-budget", "1")]
    [InlineData("--error-budget", "must lie strictly between 0 and 1, got -0.01", "--error-budget", "-0.01")]
    [InlineData("--error-budget", "must lie strictly between 0 and 1, got 2", "--error-budget", "2")]
    [InlineData("--error-budget", "must lie strictly between 0 and 1, got NaN", "--error-budget", "NaN")]
    [InlineData("--error-budget", "Cannot parse argument 'lots'", "--error-budget", "lots")]
    [InlineData("--qpus", "must be at least 1, got 0", "--qpus", "0")]
    [InlineData("--qpus", "must be at least 1, got -3", "--qpus", "-3")]
    [InlineData("--models", "unknown qubit model 'qubit_gate_ns_e9'", "--models", "qubit_gate_ns_e9")]
    [InlineData("--models", "the floquet_code needs a Majorana model", "--models", "qubit_gate_us_e4:floquet_code")]
    [InlineData("--pixel", "applies to one ray's estimates", "--pixel", "1,1")] // one ray and a frame
    [InlineData("--iterations", "applies to one ray's estimates", "--iterations", "3")]
    [InlineData("--subpixels", "applies to one ray's estimates", "--subpixels", "4")]
    [InlineData("--pooled", "applies to one ray's estimates", "--pooled", "4")]
    [InlineData("--seed", "Cannot parse argument '-1'", "--seed", "-1")]
    [InlineData("--passes", "must be at least 1, got 0", "--passes", "0")]
    public void FrameUsageErrors(string option, string problem, params string[] options) =>
        Outcome.Of(["estimate", "--frame", Scene, "--size", "4", .. options]).AssertUsageError(option, problem);

    [Theory]
    [InlineData("--error-budget", "--error-budget", "0.01")]
    [InlineData("--qpus", "--qpus", "4")]
    [InlineData("--output", "-o", "frame.csv")]
    [InlineData("--passes", "--passes", "2")]
    [InlineData("--seed", "--seed", "3")]
    public void FrameOptionsNeedTheFrame(string option, params string[] options) =>
        Outcome.Of(["estimate", Scene, .. options]).AssertUsageError(option, "needs --frame");

    [Fact]
    public void FramePricingOnAClusterCostsTheSame()
    {
        Assert.Equal(1, ConsoleCapture.Run(["estimate", Scene, "--cluster", "cluster.json"]).Code); // one ray's estimates need no cluster
        var runs = frames.Value;
        Assert.Equal((0, 0), (runs.LocalCode, runs.ClusterCode));
        Assert.True(runs.Served.First > 0 && runs.Served.Second > 0, $"jobs served: {runs.Served.First} and {runs.Served.Second}; both workers should take some");

        var (here, there) = (runs.Local, runs.OnCluster);
        // The Resource Estimator is deterministic: the same runs priced anywhere cost the same.
        Assert.Equal(here["figures"]!["cost"]!.ToJsonString(), there["figures"]!["cost"]!.ToJsonString());
        Assert.Equal((RunPlace.LocalKind, 1), ((string)here["ranOn"]!["kind"]!, (int)here["ranOn"]!["bridges"]!));
        Assert.Equal((RunPlace.ClusterKind, 2, 2), ((string)there["ranOn"]!["kind"]!, (int)there["ranOn"]!["bridges"]!, (int)there["ranOn"]!["workers"]!));
    }

    [Fact]
    public void FrameWritesItsTableAsMarkdownAndCsvAndKeepsOtherFiles()
    {
        var runs = frames.Value;
        Assert.Equal((0, 0), (runs.LocalCode, runs.ClusterCode));
        var lines = runs.Markdown;
        Assert.Equal(GeneratedReport.MarkdownMarker("qrt estimate --frame"), lines[0]);
        var header = lines.Single(l => l.StartsWith("| measure |", StringComparison.Ordinal));
        Assert.EndsWith("| total |", header);
        Assert.Contains(lines, l => l.StartsWith("| qubit_gate_ns_e3, surface_code: runtime, 2 QPUs |", StringComparison.Ordinal));

        var rows = runs.Csv.Where(l => !l.StartsWith('#')).ToArray();
        Assert.StartsWith("measure,", rows[0]);
        Assert.Contains(rows, r => r.StartsWith("CCZ,", StringComparison.Ordinal));

        string[] frame = ["estimate", "--frame", Scene, "--size", "1", "--qpus", "2", "--workers", "1"];
        var notes = Path.ChangeExtension(Path.Combine(_scratch.Path, "notes"), "md");
        File.WriteAllText(notes, "# my notes\n");
        Assert.Equal(ExitCodes.BadInput, ConsoleCapture.Run([.. frame, "-o", notes]).Code);
        Assert.Equal("# my notes\n", File.ReadAllText(notes));
    }

    [Fact]
    public void FrameSweepWritesItsReportAndPlot()
    {
        var output = Path.Combine(_scratch.Path, "frame-sweep.md");
        var plot = Path.Combine(_scratch.Path, "frame-sweep-runtime-vs-primitives.png");
        // What an earlier run of the same command left: it replaces both.
        File.WriteAllText(output, GeneratedReport.MarkdownMarker(EstimateFrameSweepCommand.CommandText) + "\nan earlier report\n");
        ImageFiles.Write([(new RgbImage(1, 1), plot)]);
        // 1x1 frames, the smallest whose primary and shadow passes both make Grover runs.
        string[] sweep = ["estimate", "frame-sweep", "--sizes", "1", "--primitives", "8", "--scaling-size", "1", "--detailed-size", "1", "--models", "qubit_gate_ns_e3", "--workers", "1", "-o", output];
        Assert.Equal(0, ConsoleCapture.Run(sweep).Code);
        var lines = File.ReadAllLines(output);
        Assert.DoesNotContain("an earlier report", lines);
        Assert.Equal(GeneratedReport.MarkdownMarker(EstimateFrameSweepCommand.CommandText), lines[0]);
        // Each scene at the one size in the logical table, the model's table and the per-pixel table; N in the
        // logical, runtime and qubit tables.
        foreach (var scene in new[] { "Qornell-64", "Depth Complexity 64" })
            Assert.Equal(3, lines.Count(l => l.StartsWith($"| {scene} | 1x1 |", StringComparison.Ordinal)));
        Assert.Equal(3, lines.Count(l => l.StartsWith("| 8 | ", StringComparison.Ordinal)));
        Assert.Contains(lines, l => l.Contains("(frame-sweep-runtime-vs-primitives.png)", StringComparison.Ordinal));
        Assert.Equal(QuantumRayTracing.Estimates.FramePlots.Width, ImageReader.Read(plot).Width);
    }

    [Fact]
    public void SweepWritesItsReportWithThePapersFigure()
    {
        var output = Path.Combine(_scratch.Path, "oracle-sweep.md");
        // What an earlier run of the same command left: regenerating replaces it.
        File.WriteAllText(output, GeneratedReport.MarkdownMarker(EstimateOracleSweepCommand.CommandText) + "\nan earlier report\n");
        Assert.Equal(0, ConsoleCapture.Run(["estimate", "oracle-sweep", "--primitives", "4", "8", "--bits", "2", "--ablation", "4", "--no-circuit", "--workers", "1", "-o", output]).Code);
        var lines = File.ReadAllLines(output);
        Assert.DoesNotContain("an earlier report", lines);
        Assert.Equal(GeneratedReport.MarkdownMarker(EstimateOracleSweepCommand.CommandText), lines[0]);
        Assert.Contains("| paper, simulator (Qiskit) | 19 | 2165 | 1185 | Qiskit's, after its decomposition (not stated further) |", lines);
        Assert.Contains("| paper, transpiled for ibmq_paris | 27 | 18277 | 11096 | the device's native gates, routed on its 27 qubits |", lines);
        // The device experiment at the device's width: table 9's two rows and ours (the device construction fits 27 qubits).
        Assert.Equal(["paper's table 9: simulator", "paper's table 9: transpiled for ibmq_paris", "ours, compact: search run (prepare, 1 iteration, measure)",
            "ours, compact: the oracle Int_r once", "ours, device: search run (prepare, 1 iteration, measure)", "ours, device: the oracle Int_r once"],
            DataRows(lines, "## The paper's device experiment at the device's width"));
        Assert.Contains(lines, l => l.StartsWith("| ours, device: search run", StringComparison.Ordinal) && l.EndsWith("| yes |", StringComparison.Ordinal));
        // One row per requested N and bit count in the before → after tables.
        Assert.Equal(["4", "8"], DataRows(lines, "## The oracle against the number of primitives"));
        Assert.Equal(["2"], DataRows(lines, "## The oracle against the coordinate bits"));
        // Every plot the report shows is a PNG beside it (none when the build has no plot writer).
        foreach (var png in lines.Where(l => l.StartsWith("![", StringComparison.Ordinal)).Select(l => l[(l.LastIndexOf('(') + 1)..^1]))
            Assert.Equal(800, ImageReader.Read(Path.Combine(_scratch.Path, png)).Width);
    }

    /// <summary>The first cell of each data row of the table in the section starting with <paramref name="heading"/>.</summary>
    private static string[] DataRows(string[] lines, string heading)
    {
        var start = Array.FindIndex(lines, l => l.StartsWith(heading, StringComparison.Ordinal));
        Assert.True(start >= 0, $"no section '{heading}'");
        return lines.Skip(start + 1).TakeWhile(l => !l.StartsWith("## ", StringComparison.Ordinal))
            .Where(l => l.StartsWith("| ", StringComparison.Ordinal)).Skip(1) // the header row
            .Select(l => l.Split('|')[1].Trim()).ToArray();
    }

    [Fact]
    public void SweepRefusesToReplaceAFileItDidNotWrite()
    {
        var output = Path.ChangeExtension(Path.Combine(_scratch.Path, "notes"), "md");
        File.WriteAllText(output, "# my notes\n");
        Assert.Equal(ExitCodes.BadInput, ConsoleCapture.Run(["estimate", "oracle-sweep", "--primitives", "4", "--bits", "2", "--no-circuit", "-o", output]).Code);
        Assert.Equal("# my notes\n", File.ReadAllText(output));
    }
}
