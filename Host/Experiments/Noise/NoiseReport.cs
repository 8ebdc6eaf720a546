using System.Globalization;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Experiments;
/// <summary>The report `qrt bench noise` writes (docs/noise.md): a section per part measured, with its tables and plots.</summary>
public static partial class NoiseReport
{
    /// <summary>
    /// Absolute gap allowed between the approximation and the simulator before sampling error: the
    /// approximation's own error on the supersampling circuits, measured in their check (largest |gap| − Z·σ at s = 2/3 over
    /// every case there, rounded up). The tests use the same tolerance.
    /// </summary>
    public const double ModelTolerance = 0.06;

    /// <summary>The paper's table 9: qubits, gates and depth of the oracle transpiled for ibmq_paris.</summary>
    public const int DeviceQubits = 27, DeviceGates = 18277, DeviceDepth = 11096;

    public const string Title = "Hardware noise";

    /// <summary>docs/noise.md: the parts measured, each with its tables and plots; the writer's footer names the machine and the command.</summary>
    public static Report Of(NoiseBenchResult result, NoiseBenchSettings settings)
    {
        var report = new Report(Title);
        var searchMisses = result.Check.Count(r => !r.Accepts(SearchModel.Counted, NoiseCheck.SearchTolerance, NoiseCheck.Z));
        report.Text(Lines(
            "What Pauli noise does to the quantum circuits: the noise locations of the gate-level oracle a machine would run, and which of",
            "them can harm a search; the analytic noise model of the searches checked against the noisy simulator within |gap| ≤ "
                + $"{F(NoiseCheck.SearchTolerance, "0.00")} + z·σ{(result.Check.Count == 0 ? "" : $" ({searchMisses} of {result.Check.Count} rows outside)")}, and of the",
            $"supersampling coins and QSS readouts within {F(ModelTolerance, "0.00")} + z·σ; the ray tracing paper's device experiment (sec. 8, fig. 15)",
            "reproduced on the simulator; and what noise costs a render on the gate-level oracle, beside the lookup oracle (intersections",
            "computed classically beforehand), whose circuit has far fewer noise locations."));
        Summary(report, result, settings);
        report.Text($"Measured in {F(result.Elapsed.TotalMinutes, "0.0")} min; the machine and the command that regenerates this page are named at its end.");
        if (result.Exposures.Count > 0) Exposure(report, result.Exposures, traced: settings.Parts.Contains("exposure"));
        if (settings.Parts.Contains("model")) Model(report, result.Check, settings.Shots, result.Fit);
        if (settings.Parts.Contains("supersampling")) SupersamplingCheck(report, result.Supersampling, settings.Shots);
        if (settings.Parts.Contains("device")) Device(report, result.Device, settings.DeviceShots, result.DeviceSearch!, result.DeviceOracle!, result.Machine);
        if (settings.Parts.Contains("render")) Render(report, result.Sweeps, settings.Size, result.Confirmations, settings.ConfirmSize);
        return report;
    }

    /// <summary>The page's results in a few lines before their detail: each figure is one its section below gives.</summary>
    private static void Summary(Report report, NoiseBenchResult result, NoiseBenchSettings settings)
    {
        var lines = new List<string>();
        if (settings.Parts.Contains("model") && result.Check.Count > 0)
        {
            var inside = result.Check.Count(r => r.Accepts(SearchModel.Counted, NoiseCheck.SearchTolerance, NoiseCheck.Z));
            lines.Add($"- The searches' noise model lies within {F(NoiseCheck.SearchTolerance, "0.00")} + z·σ of the noisy simulator on {inside} of {result.Check.Count} rows.");
        }
        if (settings.Parts.Contains("supersampling") && result.Supersampling.Count > 0)
            lines.Add($"- The supersampling coins' and QSS readouts' model: largest gap beyond z·σ {F(Math.Max(0, SupersamplingWorstGap(result.Supersampling)), "0.000")} "
                + $"(the tolerance is {F(ModelTolerance, "0.00")}).");
        if (settings.Parts.Contains("device") && result.Device.Count > 0)
        {
            var floor = UniformSamplingFloor(result.Device[0].Histogram.Length, settings.DeviceShots);
            var flat = NoiseBenchmark.RateAtDistance(result.Device, 2 * floor);
            var tenth = NoiseBenchmark.RateAtDistance(result.Device, 0.1);
            lines.Add($"- The paper's device experiment (fig. 15): the measured index is as flat as {settings.DeviceShots} uniform samples from "
                + $"p ≈ {(flat is { } a ? Rate(a) : "–")} per gate, within 0.1 of uniform (TVD) from p ≈ {(tenth is { } b ? Rate(b) : "–")}.");
        }
        if (settings.Parts.Contains("render") && result.Sweeps.Count > 0)
        {
            lines.Add($"- Rendering at {settings.Size}x{settings.Size}: the per-gate error p from which quantum loses (a) to brute force in Int/Ray, "
                + "(b) to the randomized renderer in NRMSE at equal Int/Ray:");
            foreach (var scene in result.Sweeps.GroupBy(s => s.Scene))
                lines.Add($"  {scene.Key}: " + string.Join("; ", scene.Select(sweep =>
                {
                    var (a, b) = Thresholds(sweep);
                    return $"{sweep.Label} (a) {a}, (b) {b}";
                })) + ".");
        }
        if (lines.Count > 0) report.Text(Lines(["**In short** (each figure from its section below):", .. lines]));
    }

    /// <summary>Where a sweep's quantum render loses: (a) to brute force in Int/Ray, (b) to the randomized renderer at equal Int/Ray.</summary>
    private static (string A, string B) Thresholds(NoisyRenderBenchmark.Sweep sweep)
    {
        var classicalPerRay = sweep.Classical.Result.Total.PerRayConservative;
        var a = sweep.Crossing(q => q.Measurement.Result.Total.PerRayConservative - classicalPerRay);
        var b = sweep.Crossing(q => sweep.RandomizedNrmseAt(q.Measurement.Result.Total.PerRayConservative) is { } r ? q.Measurement.Error.Nrmse - r : double.NaN);
        var highest = Rate(sweep.Quantum.Max(q => q.PerGate));
        return (a is { } x ? Rate(x) : $"none up to {highest}", b is { } y ? Rate(y) : $"none up to {highest}");
    }

    /// <summary>The supersampling check's largest gap beyond z·σ (negative when every row is inside z·σ).</summary>
    private static double SupersamplingWorstGap(IReadOnlyList<SupersamplingCheckRow> rows) =>
        rows.Max(r => Math.Abs(r.Observed - r.Predicted(DepolarizingApproximation.Default)) - NoiseCheck.Z * r.StandardError(DepolarizingApproximation.Default));

    // One paragraph of several source lines, kept as the lines of the Markdown.
    private static string Lines(params string[] lines) => string.Join('\n', lines);

    private static string F(double value, string format) => value.ToString(format, CultureInfo.InvariantCulture);

    private static string I(long value) => value.ToString(CultureInfo.InvariantCulture);

    private static string Rate(double p) => p == 0 ? "0" : p.ToString("0.#e0", CultureInfo.InvariantCulture);
}
