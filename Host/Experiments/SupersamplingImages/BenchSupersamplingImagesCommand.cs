using System.CommandLine;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Experiments;

/// <summary>`bench supersampling-images`: options → <see cref="SupersamplingImagesSettings"/> → <see cref="SupersamplingImagesExperiment"/> (docs/supersampling-images.md).</summary>
public sealed class BenchSupersamplingImagesCommand : Command
{
    public const string CommandText = "qrt bench supersampling-images";

    private readonly Option<int> _seeds = CommonOptions.SeedCount("Seeds 1..S per configuration; tables give mean ± standard deviation over them, images show seed 1.", 5, max: 100);

    private readonly Option<int[]> _sizes = CommonOptions.SquareSizes("Output sizes for the thesis's tables (4x4 subpixels: rendered at 4 times each).", [64, 128, 256], max: 512);

    private readonly BenchReportOptions _report = new(CommandText, "docs/supersampling-images.md; CSVs and PNGs go beside it as <name>.csv, <name>-confidence.csv, <name>-*.png");

    public BenchSupersamplingImagesCommand() : base("supersampling-images", "Supersampling on rendered images: paper 003's fig. 1 (8x8 subpixels, 240 queries), thesis 004's tables 4.1/4.2 (4x4), and the confidence map against the error (analytic engine).")
    {
        Aliases.Add("supersample-images"); // its earlier name: scripts that use it still work
        this.AddOptions(_seeds, _sizes, _report.Output, _report.Csv);
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var writer = _report.Writer(parse);
        writer.EnsureWritable(SupersamplingImagesExperiment.Pictures);
        writer.EnsureDataWritable(SupersamplingImagesExperiment.DataTables);
        var settings = new SupersamplingImagesSettings(parse.GetValue(_seeds), parse.GetValue(_sizes)!);
        var report = SupersamplingImagesExperiment.Run(settings, Console.Error.WriteLine);
        writer.Write(report, ReportFooter.Lines(MachineDescription.Describe(null, null)));
        return ExitCodes.Success;
    }
}
