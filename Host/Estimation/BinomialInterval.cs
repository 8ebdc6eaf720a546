using MathNet.Numerics.Distributions;

namespace QuantumRayTracing.Estimation;

/// <summary>The two confidence intervals iterative QAE chooses between for a head probability seen as heads / flips.</summary>
public enum BinomialIntervalKind
{
    /// <summary>Clopper–Pearson: exact, from the beta distribution's quantiles.</summary>
    ClopperPearson,

    /// <summary>Chernoff–Hoeffding: p̂ ± √(ln(2/α) / (2n)), wider, in closed form.</summary>
    Chernoff,
}

/// <summary>Confidence intervals for a binomial probability, each holding the true p with probability at least 1 − α.</summary>
public static class BinomialInterval
{
    public static (double Low, double High) Of(BinomialIntervalKind kind, int heads, int flips, double alpha)
    {
        if (flips < 1 || heads < 0 || heads > flips) throw new ArgumentOutOfRangeException(nameof(heads), heads, $"heads must lie in 0..{flips} of at least one flip");
        if (kind == BinomialIntervalKind.Chernoff)
        {
            var p = (double)heads / flips;
            var half = Math.Sqrt(Math.Log(2 / alpha) / (2.0 * flips));
            return (Math.Max(0, p - half), Math.Min(1, p + half));
        }
        var low = heads == 0 ? 0 : Beta.InvCDF(heads, flips - heads + 1, alpha / 2);
        var high = heads == flips ? 1 : Beta.InvCDF(heads + 1, flips - heads, 1 - alpha / 2);
        return (low, high);
    }
}
