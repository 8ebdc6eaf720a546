using System.CommandLine;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Cluster;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Experiments;

/// <summary>`bench cluster-performance`: options → <see cref="ClusterPerformanceSettings"/> → <see cref="ClusterPerformanceExperiment"/> (docs/cluster-performance.md).</summary>
public sealed class BenchClusterPerformanceCommand : Command
{
    private readonly BenchReportOptions _report = new("qrt bench cluster-performance", "docs/cluster-performance.md");

    private readonly Option<FileInfo?> _cluster = CommonOptions.Cluster("The cluster file of the running workers (docs/cluster.md). Default: none; the benchmark needs one.", required: true);

    private readonly Option<int> _size = CommonOptions.SquareSize("Side of the square render of the Qornell box with 64 primitives, in pixels.", 32);

    private readonly Option<int> _requests = new Option<int>("--requests") { Description = "Bridge requests timed one at a time on each path.", DefaultValueFactory = _ => 200 }.Between(1, 100_000);

    private readonly Option<int> _frameSize = new Option<int>("--frame-size")
    {
        Description = "Side of the analytic frame rendered by this process alone and by the cluster's workers in tiles; 0 skips it.",
        DefaultValueFactory = _ => 4096,
    }.Between(0, Scenes.SceneLoader.MaxImageSide);

    public BenchClusterPerformanceCommand() : base("cluster-performance", "A fullstate render and single bridge requests on local bridges against a cluster's workers, and a large analytic frame in tiles on the workers against this process alone.")
    {
        Aliases.Add("cluster"); // its earlier name: scripts that use it still work
        this.AddOptions(_cluster, _size, _requests, _frameSize);
        _report.AddTo(this);
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var writer = _report.Writer(parse);
        var scene = _report.Load(parse, "qornell-64");
        using var cluster = ClusterBridges.Start(parse.GetValue(_cluster)!.FullName, parse.GetValue(_report.Workers));
        var settings = new ClusterPerformanceSettings(scene, parse.GetValue(_size), parse.GetValue(_requests), parse.GetValue(_report.Seed), parse.GetValue(_report.Workers), cluster, parse.GetValue(_frameSize));
        var report = ClusterPerformanceExperiment.Run(settings, Console.Error.WriteLine);
        writer.Write(report, ReportFooter.Lines(MachineDescription.Describe(null, null)));
        return ExitCodes.Success;
    }
}
