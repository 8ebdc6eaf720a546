using System.CommandLine;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Noise;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// `bench noise`: the depolarizing approximation against the noisy simulator (searches, coins and QSS), the paper's device experiment
/// (fig. 15) under Pauli noise, and rendering under noise; writes docs/noise.md and its plots.
/// </summary>
public sealed class BenchNoiseCommand : Command
{
    public const string CommandText = "qrt bench noise";

    private readonly BenchReportOptions _report = new(CommandText, "docs/noise.md");

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
        Description = $"Pixels per side of the renders of {NoiseBenchSettings.ConfirmSceneName} on the noisy gate engine that confirm the analytic model (0 skips them).",
        DefaultValueFactory = _ => 8,
    }.Between(0, 128);

    private readonly Option<double[]> _confirmRates = new("--confirm-rates")
    {
        Description = "Per-gate error rates of the gate-engine confirmation renders (space-separated).",
        DefaultValueFactory = _ => [1e-4, 1e-3, 3e-3],
        AllowMultipleArgumentsPerToken = true,
    };

    private readonly Option<FileInfo> _exposureTable = new("--exposure-table")
    {
        Description = "Where the exposure part writes the gate-level oracle's traced noise exposure per circuit shape (the table the analytic engine reads, built in).",
        DefaultValueFactory = _ => new FileInfo("Host/Noise/gate-level-exposure.json"),
    };

    private readonly Option<string[]> _parts = new("--parts")
    {
        Description = "Which parts to run and report: exposure (the gate-level oracle's noise exposure, traced for every scene of the scene directory up to N = 64), model (the approximation against the simulator), supersampling (the same for the coins and QSS readouts), device (fig. 15), render (rendering under noise).",
        DefaultValueFactory = _ => NoiseBenchSettings.AllParts,
        AllowMultipleArgumentsPerToken = true,
    };

    public BenchNoiseCommand() : base("noise", "Hardware noise: the analytic noise model against the noisy simulator, the paper's device experiment (fig. 15), rendering under noise; -o docs/noise.md.")
    {
        this.AddOptions(_shots, _deviceShots, _size, _confirmSize, _confirmRates, _parts, _exposureTable);
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
        // Without the exposure part its section reports the built-in table for the same scenes.
        var exposureScenes = parts.Contains("exposure") || parts.Contains("render")
            ? parse.GetValue(_report.SceneDirectory)!.GetFiles("*.json").OrderBy(f => f.Name, StringComparer.Ordinal)
                .Select(f => (Path.GetFileNameWithoutExtension(f.Name), Scenes.SceneLoader.Load(f.FullName)))
                .Where(s => s.Item2.Primitives.Count <= NoiseBenchSettings.MaxExposurePrimitives).ToArray()
            : [];
        var settings = new NoiseBenchSettings(parts, parse.GetValue(_shots), parse.GetValue(_deviceShots), scenes, parse.GetValue(_size),
            parse.GetValue(_confirmSize), parse.GetValue(_confirmRates)!, parse.GetValue(_report.Workers), ExposureScenes: exposureScenes,
            ConfirmScene: parts.Contains("render") && parse.GetValue(_confirmSize) > 0 ? (NoiseBenchSettings.ConfirmSceneName, _report.Load(parse, NoiseBenchSettings.ConfirmSceneName)) : null);
        writer.EnsureWritable(settings.PlotNames());
        using var cluster = _report.StartBridges(parse);
        var (report, machine, exposures) = NoiseExperiment.Run(settings with { Pool = cluster }, Console.Error.WriteLine);
        if (parts.Contains("exposure") && exposures.Count > 0) File.WriteAllText(parse.GetValue(_exposureTable)!.FullName, GateLevelExposureTable.ToJson(exposures.Select(e => (e.Key, e.Exposure))).ToJsonString(new() { WriteIndented = true }) + "\n");
        writer.Write(report, ReportFooter.Lines(machine, cluster));
        return ExitCodes.Success;
    }
}
