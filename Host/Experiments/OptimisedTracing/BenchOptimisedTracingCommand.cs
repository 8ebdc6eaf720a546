using System.CommandLine;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Experiments;

/// <summary>`bench optimised-tracing`: options → <see cref="OptimisedTracingSettings"/> → <see cref="OptimisedTracingExperiment"/> (docs/optimised-tracing.md).</summary>
public sealed class BenchOptimisedTracingCommand : Command
{
    public const string CommandText = "qrt bench optimised-tracing";

    private readonly Option<int> _size = CommonOptions.SquareSize("Square image size (the paper: 128).", 128);

    private readonly BenchReportOptions _report = new(CommandText, "docs/optimised-tracing.md");

    public BenchOptimisedTracingCommand() : base("optimised-tracing", "The paper's tables 5-8 (neighbour gathering, false-negative estimates, termination, randomized classical) and our default configuration, on the analytic engine.")
    {
        Aliases.Add("optimised"); // its earlier name: scripts that use it still work
        Options.Add(_size);
        _report.AddTo(this);
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var writer = _report.Writer(parse);
        var settings = new OptimisedTracingSettings(stem => _report.Load(parse, stem), parse.GetValue(_size), parse.GetValue(_report.Seed), parse.GetValue(_report.Workers));
        var report = OptimisedTracingExperiment.Run(settings, Console.Error.WriteLine);
        writer.Write(report, ReportFooter.Lines(MachineDescription.Describe(null, null)));
        return ExitCodes.Success;
    }
}
