using QuantumRayTracing.Engines;
using QuantumRayTracing.Tests.Statistics;

namespace QuantumRayTracing.Tests.Engines;

/// <summary>Statistical checks any engine must pass: the same for analytic and fullstate.</summary>
public static class EngineDistributionChecks
{
    /// <summary>The share of marked outcomes after r iterations is sin²((2r+1)θ), sin²θ = t/N, for every hard case.</summary>
    public static void SuccessMatchesClosedForm(IGroverEngine engine, int shots)
    {
        var cases = GroverCase.Hard;
        var requests = cases.SelectMany(c => Enumerable.Repeat(c.Request, shots)).ToArray();
        var measured = engine.Measure(requests);
        for (var c = 0; c < cases.Length; c++)
        {
            var set = cases[c].Request.Marked;
            var hits = 0;
            for (var s = 0; s < shots; s++)
            {
                var index = measured[c * shots + s];
                Assert.InRange(index, 0, set.Count - 1);
                if (set.Contains(index)) hits++;
            }
            var theta = Math.Asin(Math.Sqrt((double)set.MarkedCount / set.Count));
            var expected = set.MarkedCount == set.Count ? 1.0 : Math.Pow(Math.Sin((2 * cases[c].Iterations + 1) * theta), 2);
            StatisticalBounds.AssertBinomial(hits, expected, shots, $"{engine.Name}, {cases[c]}");
        }
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
