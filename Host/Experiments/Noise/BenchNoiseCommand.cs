using System.CommandLine;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// `bench noise`: the depolarizing approximation against the noisy simulator (searches, coins and QSS), the paper's device experiment
/// (fig. 15) under Pauli noise, and rendering under noise; writes docs/noise.md and its plots.
/// </summary>
public sealed class BenchNoiseCommand : Command
{
    public const string CommandLine = "qrt bench noise";

    private readonly BenchReportOptions _report = new(CommandLine, "docs/noise.md");

    private readonly Option<int> _shots = new Option<int>("--shots")
    {
        Description = "Runs per case of the model checks (searches, coins and QSS).",
        DefaultValueFactory = _ => 2000,
    }.Between(100, 1_000_000);

    private readonly Option<int> _deviceShots = new Option<int>("--device-shots")
    {
        Description = "Measurements per error rate of the device experiment (the paper's fig. 15 took 1024).",
        DefaultValueFactory = _ => 1024,
    }.Between(16, 1_000_000);

    private readonly Option<int> _size = CommonOptions.SquareSize("Pixels per side of the noisy renders on the analytic engine.", 128);

    private readonly Option<int> _confirmSize = new Option<int>("--confirm-size")
    {
        Description = "Pixels per side of the renders on the noisy fullstate engine that confirm the analytic model (0 skips them).",
        DefaultValueFactory = _ => 32,
    }.Between(0, 128);

    private readonly Option<double[]> _confirmRates = new("--confirm-rates")
    {
        Description = "Per-gate error rates of the fullstate confirmation renders (space-separated).",
        DefaultValueFactory = _ => [1e-4, 1e-3, 1e-2],
        AllowMultipleArgumentsPerToken = true,
    };

    private readonly Option<string[]> _parts = new("--parts")
    {
        Description = "Which parts to run and report: model (the approximation against the simulator), supersampling (the same for the coins and QSS readouts), device (fig. 15), render (rendering under noise).",
        DefaultValueFactory = _ => NoiseBenchSettings.AllParts,
        AllowMultipleArgumentsPerToken = true,
    };

    public BenchNoiseCommand() : base("noise", "Hardware noise: the analytic noise model against the noisy simulator, the paper's device experiment (fig. 15), rendering under noise; -o docs/noise.md.")
    {
        this.AddOptions(_shots, _deviceShots, _size, _confirmSize, _confirmRates, _parts);
        _report.AddTo(this, seed: false, cluster: true);
        _confirmRates.Validators.Add(r =>
        {
            if (r.TryGetValue<double[]>(out var rates) && (rates ?? []).Any(p => !(p > 0 && p <= 1))) r.AddError("--confirm-rates: each rate must lie in (0, 1]");
        });
        _parts.Validators.Add(r =>
        {
            if (r.TryGetValue<string[]>(out var parts))
                foreach (var part in parts ?? [])
                    if (!NoiseBenchSettings.AllParts.Contains(part)) r.AddError($"--parts: '{part}' is not one of {string.Join(", ", NoiseBenchSettings.AllParts)}");
        });
        SetAction(Execute);
    }

    private int Execute(ParseResult parse)
    {
        var writer = _report.Writer(parse);
        var parts = parse.GetValue(_parts)!.ToHashSet();
        var scenes = parts.Contains("render")
            ? NoiseBenchSettings.RenderScenes.Select(n => (n, _report.Load(parse, n))).ToArray()
            : [];
        var settings = new NoiseBenchSettings(parts, parse.GetValue(_shots), parse.GetValue(_deviceShots), scenes, parse.GetValue(_size),
            parse.GetValue(_confirmSize), parse.GetValue(_confirmRates)!, parse.GetValue(_report.Workers));
        writer.EnsureWritable(settings.PlotNames());
        using var cluster = _report.StartBridges(parse);
        var (report, machine) = NoiseExperiment.Run(settings with { Pool = cluster }, Console.Error.WriteLine);
        writer.Write(report, ReportFooter.Lines(machine, cluster));
        return ExitCodes.Success;
    }
}
