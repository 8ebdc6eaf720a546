using System.CommandLine;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Experiments;

/// <summary>`bench grover-performance`: options → <see cref="GroverPerformanceSettings"/> → <see cref="GroverPerformanceExperiment"/> (docs/grover-performance.md).</summary>
public sealed class BenchGroverPerformanceCommand : Command
{
    public const string CommandText = "qrt bench grover-performance";

    private readonly Option<int[]> _sizes = CommonOptions.List("--sizes", "Search sizes N (space-separated).", [8, 64, 512], "N", 1, 4096);

    private readonly Option<int[]> _batches = new("--batches")
    {
        Description = "Requests per engine call (space-separated).",
        DefaultValueFactory = _ => [1, 100, 1000],
        AllowMultipleArgumentsPerToken = true,
    };

    private readonly BenchReportOptions _report = new(CommandText, "docs/grover-performance.md");

    public BenchGroverPerformanceCommand() : base("grover-performance", "Cost per Grover run: fullstate (1 worker and all workers) and analytic, for each N and batch size.")
    {
        Aliases.Add("grover"); // its earlier name: scripts that use it still work
        this.AddOptions(_sizes, _batches);
        _report.AddTo(this, scenes: false, cluster: true);
        _batches.Validators.Add(r =>
        {
            if (r.TryGetValue<int[]>(out var batches) && (batches ?? []).Any(b => b < 1)) r.AddError("--batches: each batch size must be at least 1");
        });
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var writer = _report.Writer(parse);
        using var cluster = _report.StartBridges(parse);
        var settings = new GroverPerformanceSettings(parse.GetValue(_sizes)!, parse.GetValue(_batches)!, parse.GetValue(_report.Workers), parse.GetValue(_report.Seed), cluster);
        var report = GroverPerformanceExperiment.Run(settings, Console.Error.WriteLine);
        var tools = ToolVersions.Detect();
        writer.Write(report, ReportFooter.Lines(MachineDescription.Describe(tools.QsharpLang, tools.Node), cluster));
        return ExitCodes.Success;
    }
}
