using System.CommandLine;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Experiments;

/// <summary>`bench light-transport`: options → <see cref="LightTransportSettings"/> → <see cref="LightTransportExperiment"/> (docs/light-transport.md and its images).</summary>
public sealed class BenchLightTransportCommand : Command
{
    public const string CommandText = "qrt bench light-transport";

    /// <summary>The area-light scene measured, from the scene directory.</summary>
    public const string SceneStem = "qornell-64-area";

    private readonly Option<int> _size = CommonOptions.SquareSize("Square image size of the measured renders.", 32);

    private readonly Option<int> _imageSize = CommonOptions.SquareSize("Square size of the images at equal queries written beside the report (rendered apart, seed 1).", 64, "--image-size");

    private readonly Option<int> _areaSamples = CommonOptions.AreaSamples("Samples in each shading point's set (a power of two: the register a coin puts in superposition).")
        .Must(n => LightEstimation.IsRegisterSize(n) ? null : $"--area-samples {n} is not a power of two (the register a coin puts in superposition holds 2^k samples)");

    private readonly Option<int[]> _queries = CommonOptions.List("--queries", "Queries per point and light, space-separated; at least two distinct counts for the fits.",
        [16, 32, 64, 128, 256, 512, 1024, 2048, 4096], "count", LightEstimation.MinQueries, LightEstimation.MaxQueries)
        .Must(values => (values ?? []).Distinct().Count() < 2 ? "--queries: the fits need at least two distinct query counts" : null);

    private readonly Option<int[]> _imageQueries = CommonOptions.List("--image-queries", "Queries per point and light of the images at equal queries, one row of images each.",
        [64, 1024], "count", LightEstimation.MinQueries, LightEstimation.MaxQueries);

    private readonly Option<int> _seeds = CommonOptions.SeedCount("Seeds 1..S of every estimator and query count; the slopes' intervals are over them.", 8, max: 100);

    private readonly Option<int> _referenceSamples = CommonOptions.ReferenceSamples("Area samples per point of the converged classical reference.", min: 1);

    private readonly BenchReportOptions _report = new(CommandText, "docs/light-transport.md; the plots and images go beside it as <name>-<picture>.png, and only with it");

    public BenchLightTransportCommand() : base("light-transport", "Area light estimated as a mean over each point's samples: Monte Carlo against QCoin, MLAE, IQAE and BAE, error against queries per point with fitted slopes, the queries to 1 % NRMSE and images at equal queries (analytic engine).")
    {
        this.AddOptions(_size, _imageSize, _areaSamples, _queries, _imageQueries, _seeds, _referenceSamples);
        _report.AddTo(this, seed: false, workers: false);
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var queries = parse.GetValue(_queries)!.Distinct().Order().ToArray();
        var writer = _report.Writer(parse);
        var imageQueries = parse.GetValue(_imageQueries)!.Distinct().Order().ToArray();
        writer.EnsureWritable(LightTransportExperiment.Pictures(imageQueries));
        var images = parse.GetValue(_report.Output) is not null;
        var settings = new LightTransportSettings(_report.Load(parse, SceneStem), $"Scenes/{SceneStem}.json", parse.GetValue(_size), parse.GetValue(_areaSamples), queries,
            parse.GetValue(_seeds), parse.GetValue(_referenceSamples), images ? parse.GetValue(_imageSize) : null, imageQueries);
        var report = LightTransportExperiment.Run(settings, Console.Error.WriteLine);
        writer.Write(report, ReportFooter.Lines(MachineDescription.Describe(null, null)));
        return ExitCodes.Success;
    }
}
