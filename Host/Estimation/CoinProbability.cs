namespace QuantumRayTracing.Estimation;

/// <summary>
/// The exact outcome distributions of the supersampling circuits, from their rotation angle: a coin with
/// head probability sin²θ gives a head with probability sin²((2m+1)θ) after m Grover operators, and
/// the QSS counter reads y with probability ½K(y/P − θ/π) + ½K(y/P + θ/π), K the Fejér kernel of P = 2^t.
/// </summary>
public static class CoinProbability
{
    /// <summary>sin θ of a coin: the head amplitude √((1/N) Σ a_i²) (mean and direct coins) or |(1/N) Σ a_i| (shifted), clamped into [0, 1].</summary>
    public static double HeadAmplitude(CoinKind kind, IReadOnlyList<double> amplitudes)
    {
        var squares = kind != CoinKind.Shifted;
        var sum = 0.0;
        foreach (var a in amplitudes) sum += squares ? a * a : a;
        var mean = sum / amplitudes.Count;
        return Math.Clamp(squares ? Math.Sqrt(mean) : Math.Abs(mean), 0, 1);
    }

    /// <summary>Probability of a head after <paramref name="iterations"/> Grover operators on a coin of head amplitude sin θ.</summary>
    public static double Head(double headAmplitude, int iterations)
    {
        var theta = Math.Asin(Math.Clamp(headAmplitude, 0, 1));
        var s = Math.Sin((2.0 * iterations + 1) * theta);
        return Math.Clamp(s * s, 0, 1);
    }

    /// <summary>
    /// Probability the ancilla of the single-ancilla phase-estimation shot (<see cref="AncillaPhaseRequest"/>) reads 0 after
    /// k controlled Grover operators on a coin of head amplitude sin θ: ½ + ½·cos(2kθ) = cos²(kθ).
    /// </summary>
    public static double AncillaZero(double headAmplitude, int power)
    {
        var c = Math.Cos(power * Math.Asin(Math.Clamp(headAmplitude, 0, 1)));
        return Math.Clamp(c * c, 0, 1);
    }

    /// <summary>The distribution of the QSS readout for a coin whose head probability is <paramref name="mean"/>.</summary>
    public static double[] QssReadout(double mean, int counterBits)
    {
        var size = 1 << counterBits;
        var theta = Math.Asin(Math.Sqrt(Math.Clamp(mean, 0, 1)));
        var distribution = new double[size];
        var total = 0.0;
        for (var y = 0; y < size; y++)
        {
            distribution[y] = 0.5 * Fejer((double)y / size - theta / Math.PI, size) + 0.5 * Fejer((double)y / size + theta / Math.PI, size);
            total += distribution[y];
        }
        // The two kernels each sum to 1 over y; dividing removes the last rounding.
        for (var y = 0; y < size; y++) distribution[y] /= total;
        return distribution;
    }

    /// <summary>|(1/P) Σ_j e^{2πijx}|² for j in 0..P−1: 1 where x is an integer.</summary>
    private static double Fejer(double x, int size)
    {
        var denominator = Math.Sin(Math.PI * x);
        if (Math.Abs(denominator) < 1e-12) return 1;
        var ratio = Math.Sin(size * Math.PI * x) / (size * denominator);
        return ratio * ratio;
    }
}
