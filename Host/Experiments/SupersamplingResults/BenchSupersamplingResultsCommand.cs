using System.CommandLine;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Experiments;

/// <summary>`bench supersampling-results`: options → <see cref="SupersamplingResultsSettings"/> → <see cref="SupersamplingResultsExperiment"/> (docs/supersampling-results.md).</summary>
public sealed class BenchSupersamplingResultsCommand : Command
{
    public const string CommandText = "qrt bench supersampling-results";

    private readonly Option<int> _trials = CommonOptions.Trials("Uniform random means per point.", 3000, max: 1_000_000);

    private readonly BenchReportOptions _report = new(CommandText, "docs/supersampling-results.md; the CSV goes beside it with the extension .csv, the plots as <name>-error-vs-queries.png and <name>-qcoin-k.png");

    public BenchSupersamplingResultsCommand() : base("supersampling-results", "Mean estimation error against queries (analytic engine) and QSS lookup-table accuracy.")
    {
        Aliases.Add("supersample"); // its earlier name: scripts that use it still work
        Options.Add(_trials);
        _report.Seed.Description = "Seed of the means and the analytic engine.";
        this.AddOptions(_report.Seed, _report.Output, _report.Csv);
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var writer = _report.Writer(parse);
        writer.EnsureWritable(SupersamplingResultsExperiment.Pictures);
        writer.EnsureDataWritable(SupersamplingResultsExperiment.DataTables);
        var settings = new SupersamplingResultsSettings(parse.GetValue(_trials), parse.GetValue(_report.Seed));
        var report = SupersamplingResultsExperiment.Run(settings, Console.Error.WriteLine);
        writer.Write(report, ReportFooter.Lines(MachineDescription.Describe(null, null)));
        return ExitCodes.Success;
    }
}
