using System.CommandLine;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Experiments;

/// <summary>`bench fullstate-performance`: options → <see cref="FullStatePerformanceSettings"/> → <see cref="FullStatePerformanceExperiment"/> (docs/fullstate-performance.md).</summary>
public sealed class BenchFullStatePerformanceCommand : Command
{
    public const string CommandText = "qrt bench fullstate-performance";

    private readonly BenchReportOptions _report = new(CommandText, "docs/fullstate-performance.md");

    private readonly Option<string[]> _sceneNames = new("--scene-names")
    {
        Description = "Scene files (names without .json in the scene directory), space-separated.",
        DefaultValueFactory = _ => ["qornell-64", "qornell-512"],
        AllowMultipleArgumentsPerToken = true,
    };

    private readonly Option<int[]> _sizes = CommonOptions.SquareSizes("Square image sizes, space-separated.", [32, 64, 128]);

    private readonly Option<long> _baselineLimit = new("--baseline-limit")
    {
        Description = "The baseline engine (the slow one) also renders a case only up to this many pixels × primitives; 0 for never. Default: qornell-64 up to 128², qornell-512 up to 64².",
        DefaultValueFactory = _ => 2L * 64 * 64 * 512,
    };

    public BenchFullStatePerformanceCommand() : base("fullstate-performance", "Whole renders on the fullstate engine against its baseline: ms per ray, bridge calls, time in calls against simulation, and the simulator-only floor.")
    {
        Aliases.Add("fullstate"); // its earlier name: scripts that use it still work
        _report.AddTo(this, cluster: true);
        this.AddOptions(_sceneNames, _sizes, _baselineLimit);
        _baselineLimit.Validators.Add(r =>
        {
            if (r.TryGetValue<long>(out var limit) && limit < 0) r.AddError("--baseline-limit must be at least 0");
        });
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var writer = _report.Writer(parse);
        var scenes = parse.GetValue(_sceneNames)!.Select(name => (name, _report.Load(parse, name))).ToArray();
        using var cluster = _report.StartBridges(parse);
        var settings = new FullStatePerformanceSettings(scenes, parse.GetValue(_sizes)!, parse.GetValue(_baselineLimit),
            parse.GetValue(_report.Seed), parse.GetValue(_report.Workers), cluster);
        var report = FullStatePerformanceExperiment.Run(settings, Console.Error.WriteLine);
        var versions = ToolVersions.Detect();
        writer.Write(report, ReportFooter.Lines(MachineDescription.Describe(versions.QsharpLang, versions.Node), cluster));
        return ExitCodes.Success;
    }
}
