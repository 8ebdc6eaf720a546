using QuantumRayTracing.Engines;
using QuantumRayTracing.Tests.Statistics;

namespace QuantumRayTracing.Tests.Engines;

/// <summary>Statistical checks any engine must pass: the same for analytic and fullstate.</summary>
public static class EngineDistributionChecks
{
    /// <summary>The share of marked outcomes after r iterations is sin²((2r+1)θ), sin²θ = t/N, for every hard case.</summary>
    public static void SuccessMatchesClosedForm(IGroverEngine engine, int shots) => SuccessMatchesClosedForm(engine, _ => shots);

    /// <summary>As above, with each case's own number of shots.</summary>
    public static void SuccessMatchesClosedForm(IGroverEngine engine, Func<GroverCase, int> shotsOf)
    {
        var cases = GroverCase.Hard;
        var shots = cases.Select(shotsOf).ToArray();
        var requests = cases.SelectMany((c, k) => Enumerable.Repeat(c.Request, shots[k])).ToArray();
        var measured = engine.Measure(requests);
        var start = 0;
        for (var c = 0; c < cases.Length; c++)
        {
            var set = cases[c].Request.Marked;
            var hits = 0;
            for (var s = 0; s < shots[c]; s++)
            {
                var index = measured[start + s];
                Assert.InRange(index, 0, set.Count - 1);
                if (set.Contains(index)) hits++;
            }
            start += shots[c];
            var theta = Math.Asin(Math.Sqrt((double)set.MarkedCount / set.Count));
            var expected = set.MarkedCount == set.Count ? 1.0 : Math.Pow(Math.Sin((2 * cases[c].Iterations + 1) * theta), 2);
            StatisticalBounds.AssertBinomial(hits, expected, shots[c], $"{engine.Name}, {cases[c]}");
        }
    }

    /// <summary>
    /// The fewest shots, a multiple of <paramref name="step"/>, at which the binomial check of a run's marked share
    /// (acceptance interval at <see cref="StatisticalBounds.FalseFailure"/>) rejects each of the run's nearest wrong
    /// runs, one iteration fewer or more and one row fewer or more marked, with probability at least <paramref name="power"/>.
    /// Wrong runs with the same marked share cannot be told apart by this check and are left out.
    /// </summary>
    public static int ShotsFor(int count, int marked, int iterations, int step, double power = 0.99)
    {
        static double Share(int n, int t, int r) =>
            t == 0 ? 0 : t == n ? 1 : Math.Pow(Math.Sin((2 * r + 1) * Math.Asin(Math.Sqrt((double)t / n))), 2);
        var p = Share(count, marked, iterations);
        var wrong = new[] { (marked, iterations - 1), (marked, iterations + 1), (marked - 1, iterations), (marked + 1, iterations) }
            .Where(w => w.Item2 >= 0 && w.Item1 >= 0 && w.Item1 <= count)
            .Select(w => Share(count, w.Item1, w.Item2))
            .Where(q => Math.Abs(q - p) > 1e-9)
            .ToArray();
        for (var shots = step; ; shots += step)
        {
            var (low, high) = StatisticalBounds.BinomialInterval(p, shots);
            // P(the count of a wrong run falls inside the acceptance interval) = 1 − power against it.
            if (wrong.All(q => 1 - Accepted(q, shots, low, high) >= power)) return shots;
        }
    }

    private static double Accepted(double p, int shots, int low, int high)
    {
        if (p <= 0) return low == 0 ? 1 : 0;
        if (p >= 1) return high == shots ? 1 : 0;
        var binomial = new MathNet.Numerics.Distributions.Binomial(p, shots);
        return binomial.CumulativeDistribution(high) - (low > 0 ? binomial.CumulativeDistribution(low - 1) : 0);
    }

    /// <summary>Exact distribution over all N outcomes: marked share p spread evenly, the rest evenly over the unmarked.</summary>
    public static double[] ExactDistribution(GroverCase c)
    {
        var set = c.Request.Marked;
        var theta = Math.Asin(Math.Sqrt((double)set.MarkedCount / set.Count));
        var p = Math.Pow(Math.Sin((2 * c.Iterations + 1) * theta), 2);
        return Enumerable.Range(0, set.Count)
            .Select(i => set.Contains(i) ? p / set.MarkedCount : (1 - p) / (set.Count - set.MarkedCount))
            .ToArray();
    }

    public static int[] Sample(IGroverEngine engine, GroverCase c, int shots) =>
        StatisticalBounds.Histogram(engine.Measure(Enumerable.Repeat(c.Request, shots).ToArray()), c.Count);
}
