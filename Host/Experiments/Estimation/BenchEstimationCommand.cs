using System.CommandLine;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Experiments;

/// <summary>`bench estimation`: options → <see cref="EstimationSettings"/> → <see cref="EstimationExperiment"/>, composed by <see cref="EstimationReport"/> (docs/estimation.md).</summary>
public sealed class BenchEstimationCommand : Command
{
    public const string CommandText = "qrt bench estimation";

    private readonly Option<int> _trials = CommonOptions.Trials("Uniform random means per point.", 1000, max: 1_000_000);

    private readonly Option<int> _imageSize = new Option<int>("--image-size")
    {
        Description = "Output pixels per side of the Qornell box input (4x4 subpixels each; every pixel and channel one estimate).",
        DefaultValueFactory = _ => 16,
    }.Between(1, 128);

    private readonly Option<bool> _noNoise = new("--no-noise") { Description = "Skip the sweep under depolarizing decay per Grover operator." };

    private readonly BenchReportOptions _report = new(CommandText, "docs/estimation.md; the CSV goes beside it with the extension .csv, the plots as estimation-<name>.png");

    public BenchEstimationCommand() : base("estimation", "Every mean estimator (MC, QCoin, MLAE, IQAE, FAE, BAE, power-law AE, QSS, QSS with Bayesian phase estimation) by error against queries, on random means and the Qornell box's pixels, with and without noise.")
    {
        this.AddOptions(_trials, _imageSize, _noNoise);
        _report.Seed.Description = "Seed of the means and the analytic engines.";
        this.AddOptions(_report.Seed, _report.Output, _report.Csv);
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var writer = _report.Writer(parse);
        writer.EnsureWritable(EstimationReport.Pictures);
        writer.EnsureDataWritable(EstimationReport.DataTables);
        var settings = new EstimationSettings(parse.GetValue(_trials), parse.GetValue(_imageSize), !parse.GetValue(_noNoise), parse.GetValue(_report.Seed));
        var points = EstimationExperiment.Run(settings, Console.Error.WriteLine);
        writer.Write(EstimationReport.Build(points, settings), ReportFooter.Lines(MachineDescription.Describe(null, null)));
        return ExitCodes.Success;
    }
}
