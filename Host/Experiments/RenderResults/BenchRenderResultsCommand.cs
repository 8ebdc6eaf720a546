using System.CommandLine;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Experiments;

/// <summary>`bench render-results`: options → <see cref="RenderResultsSettings"/> → <see cref="RenderResultsExperiment"/> (docs/render-results.md).</summary>
public sealed class BenchRenderResultsCommand : Command
{
    public const string CommandText = "qrt bench render-results";

    private readonly Option<int> _size = CommonOptions.SquareSize("Square image size of the table 2 and 3 renders (the paper: 128).", 128);

    private readonly Option<int> _engineSize = CommonOptions.SquareSize("Square image size of the engine comparison (the full-state simulator is slow).", 32, "--engine-size");

    private readonly BenchReportOptions _report = new(CommandText, "docs/render-results.md");

    public BenchRenderResultsCommand() : base("render-results", "Renders for the paper's tables 2 and 3 (Int/Ray, NRMSE, #Dpix), an engine comparison (wall time per ray) and the gate-level oracle against the lookup form.")
    {
        Aliases.Add("render"); // its earlier name: scripts that use it still work
        this.AddOptions(_size, _engineSize);
        _report.AddTo(this, cluster: true);
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var writer = _report.Writer(parse);
        using var cluster = _report.StartBridges(parse);
        var settings = new RenderResultsSettings(stem => _report.Load(parse, stem), parse.GetValue(_size), parse.GetValue(_engineSize),
            parse.GetValue(_report.Seed), parse.GetValue(_report.Workers), cluster);
        var report = RenderResultsExperiment.Run(settings, Console.Error.WriteLine);
        writer.Write(report, ReportFooter.Lines(MachineDescription.Describe(null, null), cluster));
        return ExitCodes.Success;
    }
}
