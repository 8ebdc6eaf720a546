using MathNet.Numerics.Distributions;

namespace QuantumRayTracing.Tests.Statistics;

/// <summary>
/// Acceptance regions for statistical tests with a stated false-failure probability: a correct
/// implementation fails such a test with probability at most <see cref="FalseFailure"/>.
/// </summary>
public static class StatisticalBounds
{
    /// <summary>
    /// False-failure probability of one statistical check. No test makes more than 20 checks, so each
    /// test's false-failure probability is below 20 · 1e-8 = 2e-7.
    /// </summary>
    public const double FalseFailure = 1e-8;

    /// <summary>
    /// The smallest interval [lo, hi] of Binomial(n, p) counts whose two tails outside it each hold at
    /// most α/2. For p = 0 or 1 the interval is the single certain count.
    /// </summary>
    public static (int Low, int High) BinomialInterval(double p, int n, double alpha = FalseFailure)
    {
        if (p <= 0) return (0, 0);
        if (p >= 1) return (n, n);
        var binomial = new Binomial(p, n);
        var low = 0;
        while (low < n && binomial.CumulativeDistribution(low) <= alpha / 2) low++;
        var high = n;
        while (high > 0 && 1 - binomial.CumulativeDistribution(high - 1) <= alpha / 2) high--;
        return (low, high);
    }

    /// <summary>
    /// The one-sided Clopper–Pearson upper confidence limit of a binomial share from <paramref name="k"/> successes in
    /// <paramref name="n"/> trials: the true share exceeds it with probability at most <paramref name="alpha"/>.
    /// </summary>
    public static double ClopperPearsonUpper(long k, long n, double alpha)
    {
        if (k >= n) return 1;
        return Beta.InvCDF(k + 1, n - k, 1 - alpha);
    }

    /// <summary>The smallest count c with P(X &gt; c) ≤ <paramref name="alpha"/> for X ~ Poisson(<paramref name="mean"/>).</summary>
    public static int PoissonUpper(double mean, double alpha)
    {
        if (mean <= 0) return 0;
        var poisson = new Poisson(mean);
        var c = (int)Math.Floor(mean);
        while (1 - poisson.CumulativeDistribution(c) > alpha) c++;
        return c;
    }

    public static void AssertBinomial(int observed, double p, int n, string what)
    {
        var (low, high) = BinomialInterval(p, n);
        Assert.True(observed >= low && observed <= high,
            $"{what}: observed {observed} of {n}, expected p = {p:0.######} (count {p * n:0.#}); acceptance interval [{low}, {high}] at false-failure {FalseFailure}");
    }

    /// <summary>Pearson's statistic of observed counts against expected probabilities (cells with p = 0 must be empty).</summary>
    public static void AssertFits(IReadOnlyList<int> observed, IReadOnlyList<double> expected, string what)
    {
        var n = observed.Sum();
        var statistic = 0.0;
        var cells = 0;
        for (var k = 0; k < observed.Count; k++)
        {
            if (expected[k] == 0)
            {
                Assert.True(observed[k] == 0, $"{what}: outcome {k} has probability 0 but occurred {observed[k]} times");
                continue;
            }
            var e = expected[k] * n;
            statistic += (observed[k] - e) * (observed[k] - e) / e;
            cells++;
        }
        var critical = ChiSquared.InvCDF(cells - 1, 1 - FalseFailure);
        Assert.True(statistic <= critical, $"{what}: chi-square {statistic:0.##} exceeds {critical:0.##} (df {cells - 1}, false-failure {FalseFailure})");
    }

    /// <summary>Chi-square test of homogeneity: do two samples over the same outcomes come from one distribution.</summary>
    public static void AssertSameDistribution(IReadOnlyList<int> first, IReadOnlyList<int> second, string what)
    {
        double n1 = first.Sum(), n2 = second.Sum();
        var statistic = 0.0;
        var cells = 0;
        for (var k = 0; k < first.Count; k++)
        {
            var total = first[k] + second[k];
            if (total == 0) continue;
            var e1 = total * n1 / (n1 + n2);
            var e2 = total * n2 / (n1 + n2);
            statistic += (first[k] - e1) * (first[k] - e1) / e1 + (second[k] - e2) * (second[k] - e2) / e2;
            cells++;
        }
        var critical = ChiSquared.InvCDF(cells - 1, 1 - FalseFailure);
        Assert.True(statistic <= critical, $"{what}: homogeneity chi-square {statistic:0.##} exceeds {critical:0.##} (df {cells - 1}, false-failure {FalseFailure})");
    }

    public static int[] Histogram(IEnumerable<int> outcomes, int cells)
    {
        var counts = new int[cells];
        foreach (var o in outcomes) counts[o]++;
        return counts;
    }
}
