using System.Globalization;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// How a frame's quantum runtime (one QPU) and the classical render time grow with N: a least-squares fit of log runtime on
/// log N for each (a fit, with its range and residual), and where each qubit model's fitted runtime meets the classical one.
/// </summary>
public static class RuntimeScaling
{
    /// <summary>One qubit model's fit beside the classical render's, and their crossing.</summary>
    /// <param name="Model">The qubit model, by name.</param>
    /// <param name="Quantum">The fit of its runtime per frame on one QPU.</param>
    /// <param name="Classical">The fit of the classical render's time.</param>
    /// <param name="Crossing">The N where the two fits meet; null when they never do (parallel).</param>
    public sealed record Row(string Model, PowerLawFit Quantum, PowerLawFit Classical, double? Crossing)
    {
        /// <summary>The crossing in words: inside the measured range of N, outside it (an extrapolation), or none.</summary>
        public string CrossingText()
        {
            // Above the crossing the faster-growing runtime is the larger; quantum wins only where it is the smaller one.
            var quantumFaster = Quantum.Exponent > Classical.Exponent;
            if (Crossing is not { } n || double.IsNaN(n) || double.IsInfinity(n))
                return "none: the fits are parallel";
            var faster = quantumFaster ? "quantum" : "classical";
            if (n < 1) return $"none at any N ≥ 1 (the fits meet at N ≈ {G(n)}); {faster} grows faster, so the gap widens with N";
            var where = n >= Quantum.From && n <= Quantum.To ? "inside the measured range" : "outside the measured range (an extrapolation of the fits)";
            var side = quantumFaster ? "quantum faster below it" : "quantum faster above it";
            return $"N ≈ {G(n)}, {where}; {side}";
        }
    }

    /// <summary>
    /// The fits over <paramref name="primitives"/> of each model's runtimes (<paramref name="quantum"/>, per model, in the order
    /// of the primitives) and of the classical times; null entries where a series has fewer than two positive points.
    /// </summary>
    public static IReadOnlyList<Row> Fit(IReadOnlyList<int> primitives, IReadOnlyList<(string Model, IReadOnlyList<double> Seconds)> quantum, IReadOnlyList<double> classicalSeconds)
    {
        ArgumentNullException.ThrowIfNull(primitives);
        ArgumentNullException.ThrowIfNull(quantum);
        ArgumentNullException.ThrowIfNull(classicalSeconds);
        var classical = LogLogFit.Of(primitives.Select((n, i) => ((double)n, classicalSeconds[i])));
        if (classical is null) return [];
        var rows = new List<Row>();
        foreach (var (model, seconds) in quantum)
            if (LogLogFit.Of(primitives.Select((n, i) => ((double)n, seconds[i]))) is { } fit)
                rows.Add(new Row(model, fit, classical, fit.Crossing(classical)));
        return rows;
    }

    public static string G(double value) => value.ToString(value >= 1e4 || value < 1e-2 ? "0.0e0" : "0.##", CultureInfo.InvariantCulture);
}
