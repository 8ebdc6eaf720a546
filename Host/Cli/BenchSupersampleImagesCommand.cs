using System.CommandLine;
using QuantumRayTracing.Benchmarks;

namespace QuantumRayTracing.Cli;

/// <summary>`bench supersample-images`: options → <see cref="SupersamplingImagesSettings"/> → <see cref="SupersamplingImagesExperiment"/> (docs/supersampling-images.md).</summary>
public sealed class BenchSupersampleImagesCommand : Command
{
    public const string CommandLine = "qrt bench supersample-images";

    private readonly Option<int> _seeds = new("--seeds")
    {
        Description = "Seeds 1..S per configuration; tables give mean ± standard deviation over them, images show seed 1.",
        DefaultValueFactory = _ => 5,
    };

    private readonly Option<int[]> _sizes = new("--sizes")
    {
        Description = "Output sizes for the thesis's tables (4x4 subpixels: rendered at 4 times each).",
        DefaultValueFactory = _ => [64, 128, 256],
        AllowMultipleArgumentsPerToken = true,
    };

    private readonly BenchReportOptions _report = new(CommandLine, "docs/supersampling-images.md; CSVs and PNGs go beside it as <name>.csv, <name>-confidence.csv, <name>-*.png");

    public BenchSupersampleImagesCommand() : base("supersample-images", "Supersampling on rendered images: paper 003's fig. 1 (8x8 subpixels, 240 queries), thesis 004's tables 4.1/4.2 (4x4), and the confidence map against the error (analytic engine).")
    {
        Options.Add(_seeds);
        Options.Add(_sizes);
        Options.Add(_report.Output);
        Options.Add(_report.Csv);
        _seeds.Between(1, 100);
        _sizes.Validators.Add(r =>
        {
            if ((r.GetValueOrDefault<int[]>() ?? []).Any(n => n is < 1 or > 512)) r.AddError("--sizes: each size must be between 1 and 512");
        });
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var writer = _report.Writer(parse);
        writer.EnsureWritable(SupersamplingImagesExperiment.Pictures);
        writer.EnsureDataWritable(SupersamplingImagesExperiment.DataTables);
        var settings = new SupersamplingImagesSettings(parse.GetValue(_seeds), parse.GetValue(_sizes)!);
        var report = SupersamplingImagesExperiment.Run(settings, Console.Error.WriteLine);
        writer.Write(report, BenchReportOptions.Footer(MachineDescription.Describe(null, null)));
        return 0;
    }
}
