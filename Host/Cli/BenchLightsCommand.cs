using System.CommandLine;
using QuantumRayTracing.Benchmarks;
using QuantumRayTracing.Rendering;

namespace QuantumRayTracing.Cli;

/// <summary>`bench lights`: options → <see cref="LightsSettings"/> → <see cref="LightsExperiment"/> (docs/lights.md and its images).</summary>
public sealed class BenchLightsCommand : Command
{
    public const string CommandLine = "qrt bench lights";

    private readonly Option<int> _size = new("--size")
    {
        Description = "Square image size of the measured renders (the paper: 128).",
        DefaultValueFactory = _ => 128,
    };

    private readonly Option<int> _imageSize = new("--image-size")
    {
        Description = "Square size of the images written beside the report (rendered apart, same options).",
        DefaultValueFactory = _ => 64,
    };

    private readonly Option<int> _referenceSamples = new("--reference-samples")
    {
        Description = "Area samples and VPLs per point of the converged classical reference (the paper: 512).",
        DefaultValueFactory = _ => RenderDefaults.ReferenceSamples,
    };

    private readonly BenchReportOptions _report = new(CommandLine, "docs/lights.md; the images go beside it as <name>-<case>-<render>.png, and only with it");

    public BenchLightsCommand() : base("lights", "Area light and VPL indirect light (the paper's sec. 7): Int/Ray and error of the quantum and classical pipelines, with images beside their classical references.")
    {
        Options.Add(_size);
        Options.Add(_imageSize);
        Options.Add(_referenceSamples);
        _report.AddTo(this, workers: false);
        _size.Between(1, 1024);
        _imageSize.Between(1, 1024);
        _referenceSamples.Between(1, CommonOptions.MaxSamples);
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
        writer.Write(report, BenchReportOptions.Footer(MachineDescription.Describe(null, null)));
        return 0;
    }
}
