using System.CommandLine;
using System.Globalization;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// `bench noise-estimation`: options → <see cref="NoiseEstimationSettings"/> → <see cref="NoiseEstimationExperiment"/>, composed by
/// <see cref="NoiseEstimationReport"/> (docs/noise-estimation.md).
/// </summary>
public sealed class BenchNoiseEstimationCommand : Command
{
    public const string CommandText = "qrt bench noise-estimation";

    private readonly Option<int> _trials = CommonOptions.Trials("Estimates per point: repeated runs at f = 0.5 (fig. 10), random pixels (QSS against QCoin, MLAE and the noisy mean coin) or random means (the noise-aware comparison).", 1000, max: 100_000);

    private readonly Option<double> _deviceRate = new("--device-rate")
    {
        Description = "Per-gate depolarizing error standing in for the QCoin paper's device in fig. 10's plot and fig. 1 (the rate at which QCoin on the direct coin stops improving past k = 5).",
        DefaultValueFactory = _ => NoiseEstimationSettings.DefaultDeviceRate,
    };

    private readonly Option<int> _imageSize = new Option<int>("--image-size")
    {
        Description = "Output pixels per side of the fig. 1 image (8x8 subpixels each, rendered classically at 8 times the size).",
        DefaultValueFactory = _ => 64,
    }.Between(1, 256);

    private readonly BenchReportOptions _report = new(CommandText, "docs/noise-estimation.md");

    public BenchNoiseEstimationCommand() : base("noise-estimation", "Mean estimation under noise: the QCoin paper's fig. 10 (k against noise) and fig. 1 right (QCoin image under noise), QSS against QCoin, MLAE and the noisy mean coin against the per-gate error, and the noise-aware MLAE; -o docs/noise-estimation.md.")
    {
        this.AddOptions(_trials, _deviceRate, _imageSize);
        _report.AddTo(this, scenes: false);
        _deviceRate.Validators.Add(r =>
        {
            if (r.TryGetValue<double>(out var rate) && !NoiseEstimationSettings.StepRates.Contains(rate))
                r.AddError($"--device-rate: {rate.ToString(CultureInfo.InvariantCulture)} is not one of the swept rates {string.Join(", ", NoiseEstimationSettings.StepRates.Where(p => p > 0).Select(p => p.ToString(CultureInfo.InvariantCulture)))}");
        });
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var writer = _report.Writer(parse);
        var settings = new NoiseEstimationSettings(parse.GetValue(_trials), parse.GetValue(_deviceRate), parse.GetValue(_imageSize), parse.GetValue(_report.Seed));
        var result = NoiseEstimationExperiment.Run(settings, Console.Error.WriteLine);
        var machine = MachineDescription.Describe(null, null);
        writer.Write(NoiseEstimationReport.Build(result, settings, machine), ReportFooter.Lines(machine));
        return ExitCodes.Success;
    }
}
