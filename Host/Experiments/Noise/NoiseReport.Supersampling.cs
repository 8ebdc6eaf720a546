using QuantumRayTracing.Estimates;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Estimation;

namespace QuantumRayTracing.Experiments;

/// <summary>The supersampling circuits' model check section of docs/noise.md.</summary>
public static partial class NoiseReport
{
    /// <summary>The harmful share s fitted per coin or QSS shape; the direct coin's model has none to fit (it is exact).</summary>
    private static Dictionary<string, double> SupersamplingShares(IReadOnlyList<SupersamplingCheckRow> rows) =>
        rows.Where(r => r.Case.Kind != CoinKind.Direct).GroupBy(r => r.Case.Shape).ToDictionary(g => g.Key, g => NoiseCheck.FitHarmfulShare(g.ToArray()));

    public static void SupersamplingCheck(Report report, IReadOnlyList<SupersamplingCheckRow> rows, int shots)
    {
        var model = DepolarizingApproximation.Default;
        report.Heading("The supersampling circuits under noise: the model against the noisy simulator");
        report.Text(Lines(
            "**The approximation** (`SupersamplingNoise`, used by `supersample --engine analytic --noise p`): the same global depolarizing",
            "form. A coin flip after m Grover operators shows a head with probability Φ · sin²((2m+1)θ) + (1 − Φ) · u, and a QSS readout",
            "is the ideal distribution mixed towards uniform over its 2^t values: Φ · P(y) + (1 − Φ) / 2^t. Φ = (1 − p)^(s · L) over the",
            "circuit's noise locations L (`CoinNoiseLocations`, closed forms checked against the circuits the QDK extracts), so",
            "Φ = F₀ · F^m with F = (1 − p)^(s · L_operator) per Grover operator; the preparation and measurement count by their own",
            "locations as F₀ (not as half an operator: for the mean coin they come to about F^(1/2) anyway). u is what a maximally mixed",
            "register reads as a head: ½ for the mean coin (head = coin qubit |1⟩) and the direct coin, 1/2^(n+1) for QCoin's shifted",
            "coin, whose head also needs its n subpixel qubits at 0. The direct coin is the QCoin paper's hardware coin (sec. 6): one",
            "qubit, √(1 − f)|0⟩ + √f|1⟩ by one Ry, a Grover operator of four gates (A Z A† Z), L = 2 + 4m. Its model is exact, with no s:",
            "on one qubit a Pauli error of total probability p (p/3 each) is the depolarizing channel ρ → (1 − 4p/3) ρ + (4p/3) I/2,",
            "which commutes with every gate, so Φ = (1 − 4p/3)^L (s = 2/3 would undercount its harm: a qubit in superposition has no",
            "harmless Pauli error, and the 4/3 counts the channel's own I/2 share)."));
        report.Text(Lines(
            $"**The check.** Each circuit run {shots} times on the noisy full-state simulator (`--engine fullstate --noise p`), with",
            "the mean coin's amplitudes √F(i) and the shifted coin's F(i) − E as the estimators make them. A coin counts heads; a QSS run",
            "counts readouts at the ideal distribution's two most likely values (y and 2^t − y). Acceptance: |observed − model| ≤ δ + z·σ,",
            $"σ the binomial standard error at the model's probability, z = {F(NoiseCheck.Z, "0.00")} (two-sided false-failure 1e-6 per comparison), δ = {F(ModelTolerance, "0.00")}",
            "the approximation's own tolerance, the same as for the searches. The ideal column is the noiseless probability, which the",
            "simulator leaves far behind."));
        var check = new TextTable("supersampling-check", ["circuit", "N", "m or t", "f", "p", "L", "ideal", "observed", "model, s = 2/3 (direct: exact)", "σ", "gap", "gap/σ", "within δ + zσ", "model, fitted s"]);
        var shapes = SupersamplingShares(rows);
        foreach (var r in rows)
        {
            var c = r.Case;
            var predicted = r.Predicted(model);
            var gap = r.Observed - predicted;
            var sigma = r.StandardError(model);
            var fitted = shapes.TryGetValue(c.Shape, out var share) ? r.Predicted(new DepolarizingApproximation(share)) : predicted;
            var mean = c.Kind == CoinKind.Shifted ? c.HeadAmplitude : c.HeadAmplitude * c.HeadAmplitude;
            check.Row(c.IsQss ? "QSS" : $"{c.Kind.ToString()!.ToLowerInvariant()} coin", I(c.Subpixels), c.IsQss ? $"t = {c.CounterBits}" : $"m = {c.Iterations}", F(mean, "0.000"),
                Rate(r.Noise.PerGate), I(c.Locations), F(r.Ideal, "0.000"), F(r.Observed, "0.000"), F(predicted, "0.000"), F(sigma, "0.000"), F(gap, "+0.000;-0.000;0.000"),
                F(gap / sigma, "+0.0;-0.0;0.0"), Math.Abs(gap) <= ModelTolerance + NoiseCheck.Z * sigma ? "yes" : "**no**", F(fitted, "0.000"));
        }
        report.Table(check);
        report.Text("(f: the shifted coin's head amplitude f − E, else the mean (1/N) Σ F(i). σ: the binomial standard error at the model's probability.)");
        var worst = SupersamplingWorstGap(rows);
        var summary = new List<string> { $"Largest gap beyond z·σ at s = 2/3: {F(Math.Max(0, worst), "0.000")} (the tolerance δ is {F(ModelTolerance, "0.00")})." };
        var direct = rows.Where(r => r.Case.Kind == CoinKind.Direct).ToArray();
        if (direct.Length > 0)
            summary.Add($"The direct coin's exact model: largest |gap|/σ {F(direct.Max(r => Math.Abs(r.Observed - r.Predicted(model)) / r.StandardError(model)), "0.0")} over its {direct.Length} rows (sampling error alone).");
        var rejected = rows.Count(r => Math.Abs(r.Observed - r.Ideal) > ModelTolerance + NoiseCheck.Z * r.StandardError(model));
        summary.Add($"The ideal (noiseless) probability falls outside the same acceptance region in {rejected} of {rows.Count} rows.");
        report.Text(Lines([.. summary]));
        report.Text(Lines(
            "**Fitted s per circuit shape** (least squares in units of σ over the shape's rows), and the fidelities it gives: F per Grover",
            "operator for a coin (Φ of a whole run for QSS) at two error rates:"));
        var fits = new TextTable("supersampling-fit", ["circuit", "fitted s", "L per operator (QSS: per run)", "F at p = 1e-3, s = 2/3", "F at p = 1e-3, fitted s", "F at p = 1e-2, fitted s"]);
        foreach (var (shape, s) in shapes)
        {
            var c = rows.First(r => r.Case.Shape == shape).Case;
            long locations = c.Kind is { } kind ? CoinNoiseLocations.GroverOperator(kind, c.Amplitudes) : c.Locations;
            var fitted = new DepolarizingApproximation(s);
            fits.Row(shape, F(s, "0.000"), I(locations), F(model.Fidelity(NoiseModel.Depolarizing(1e-3), locations), "0.000"),
                F(fitted.Fidelity(NoiseModel.Depolarizing(1e-3), locations), "0.000"), F(fitted.Fidelity(NoiseModel.Depolarizing(1e-2), locations), "0.000"));
        }
        report.Table(fits);
        var series = rows.GroupBy(r => r.Case.IsQss ? $"QSS N={r.Case.Subpixels} t={r.Case.CounterBits}" : $"{r.Case.Kind.ToString()!.ToLowerInvariant()} N={r.Case.Subpixels} m={r.Case.Iterations}")
            .Select(g => (g.Key, (IReadOnlyList<(double, double)>)g.Select(r => (r.Noise.PerGate, r.Observed - r.Predicted(model))).ToArray()))
            .ToArray();
        report.Plot("supersampling-check", NoisePlots.LogX("Observed - model (coin heads, QSS peak readouts), depolarizing Pauli noise p per gate (s = 2/3; direct coin exact)", "per-gate error p", "observed - model", series, 0, "model"),
            "Gap between the noisy simulator and the depolarizing approximation of the coins and QSS against the per-gate error");
    }

    /// <summary>Expected total variation distance from uniform of <paramref name="shots"/> samples of a truly uniform source over K cells (normal approximation).</summary>
    public static double UniformSamplingFloor(int cells, int shots) =>
        0.5 * cells * Math.Sqrt(2 / Math.PI) * Math.Sqrt((1.0 / cells) * (1 - 1.0 / cells) / shots);
}
