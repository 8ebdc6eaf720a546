using System.CommandLine;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Experiments;

/// <summary>`bench speed-vs-error`: options → <see cref="SpeedVsErrorSettings"/> → <see cref="SpeedVsErrorExperiment"/> (docs/speed-vs-error.md and its plots).</summary>
public sealed class BenchSpeedVsErrorCommand : Command
{
    public const string CommandText = "qrt bench speed-vs-error";

    private readonly Option<FileInfo> _scene = new("--scene")
    {
        Description = "Scene to render.",
        DefaultValueFactory = _ => new FileInfo(Path.Combine("Scenes", "qornell-64.json")),
    };

    private readonly Option<int> _size = CommonOptions.SquareSize("Square image size (the full-state engine renders every configuration too).", 32);

    private readonly BenchReportOptions _report = new(CommandText, "docs/speed-vs-error.md; the plots go beside it as <name>-intray.png and <name>-walltime.png");

    public BenchSpeedVsErrorCommand() : base("speed-vs-error", "Speed against error for every configuration of every engine (classical, randomized, analytic, fullstate), Pareto fronts marked, with PNG plots.")
    {
        Aliases.Add("pareto"); // its earlier name: scripts that use it still work
        this.AddOptions(_scene, _size);
        _report.AddTo(this, scenes: false, cluster: true);
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var writer = _report.Writer(parse);
        writer.EnsureWritable(SpeedVsErrorExperiment.PlotNames);
        var scene = SceneLoader.Load(parse.GetValue(_scene)!.FullName);
        using var cluster = _report.StartBridges(parse);
        var settings = new SpeedVsErrorSettings(scene, parse.GetValue(_size), parse.GetValue(_report.Seed), parse.GetValue(_report.Workers), cluster);
        var report = SpeedVsErrorExperiment.Run(settings, Console.Error.WriteLine);
        writer.Write(report, ReportFooter.Lines(MachineDescription.Describe(null, null), cluster));
        return ExitCodes.Success;
    }
}
