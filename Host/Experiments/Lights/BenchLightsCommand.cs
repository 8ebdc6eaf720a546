using System.CommandLine;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Experiments;

/// <summary>`bench lights`: options → <see cref="LightsSettings"/> → <see cref="LightsExperiment"/> (docs/lights.md and its images).</summary>
public sealed class BenchLightsCommand : Command
{
    public const string CommandText = "qrt bench lights";

    private readonly Option<int> _size = CommonOptions.SquareSize("Square image size of the measured renders (the paper: 128).", 128);

    private readonly Option<int> _imageSize = CommonOptions.SquareSize("Square size of the images written beside the report (rendered apart, same options).", 64, "--image-size");

    private readonly Option<int> _referenceSamples = CommonOptions.ReferenceSamples("Area samples and VPLs per point of the converged classical reference (the paper: 512).", min: 1);

    private readonly BenchReportOptions _report = new(CommandText, "docs/lights.md; the images go beside it as <name>-<case>-<render>.png, and only with it");

    public BenchLightsCommand() : base("lights", "Area light and VPL indirect light (the paper's sec. 7): Int/Ray and error of the quantum and classical pipelines, with images beside their classical references.")
    {
        this.AddOptions(_size, _imageSize, _referenceSamples);
        _report.AddTo(this, workers: false);
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var writer = _report.Writer(parse);
        writer.EnsureWritable(LightsExperiment.ImageNames);
        var images = parse.GetValue(_report.Output) is not null;
        var settings = new LightsSettings(stem => _report.Load(parse, stem), parse.GetValue(_size), images ? parse.GetValue(_imageSize) : null,
            parse.GetValue(_referenceSamples), parse.GetValue(_report.Seed));
        var report = LightsExperiment.Run(settings, Console.Error.WriteLine);
        writer.Write(report, ReportFooter.Lines(MachineDescription.Describe(null, null)));
        return ExitCodes.Success;
    }
}
