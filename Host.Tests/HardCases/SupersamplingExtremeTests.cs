using QuantumRayTracing.Randomness;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;
using QuantumRayTracing.Tests.Engines;
using QuantumRayTracing.Tests.Statistics;

namespace QuantumRayTracing.Tests.HardCases;

/// <summary>
/// Every estimator at true means 0, 1, 1e-9 and 1 − 1e-9, on the analytic and the full-state engine, at about the
/// paper's 240 queries: estimates stay finite and in [0, 1]; at 0 and 1 they are exact (the coins are then certain:
/// no head, or no tail, can occur, and the Q# rotations by 0 and π leave no amplitude behind worth a draw).
/// </summary>
/// <remarks>
/// At ε = 1e-9 from an end, no estimator here can tell f from the end unless one of its outcomes leaves the
/// end's certain value (a head near 0, a tail near 1, a QSS readout off 0 or 2^t/2); without one each returns the end
/// itself, an error of ε. With m Grover operators a flip shows such an outcome with probability
/// sin²((2m+1)θ) ≤ (2m+1)²θ² ≤ 2.5 (2m+1)² ε (θ the angle from the end, θ² ≤ π²ε/4), and the QSS readout leaves its
/// end's value with probability at most sin²((P−1)θ) ≤ 2.5 (P−1)² ε. Summed over a run's flips, whose queries
/// add to Q = Σ (2m+1), that is at most q = 3 (2M+1) Q ε with M the largest m (for QSS M = P − 1, Q = 2P − 1). So
/// the check: error ≤ 2ε in every trial but those allowed by Binomial(trials, q) at false-failure
/// <see cref="StatisticalBounds.FalseFailure"/> (none or one or two here). Bit-plane QSS quantises both means to the
/// end and is exact there.
/// </remarks>
[Collection(QSharpCollection.Name)]
public class SupersamplingExtremeTests(FullStateFixture fixture)
{
    private const double Epsilon = 1e-9;

    /// <summary>Four subpixels each; each mean twice, once as equal values and once carried by one subpixel.</summary>
    private static readonly (double Mean, double[] Values)[] Means =
    [
        (0, [0, 0, 0, 0]),
        (1, [1, 1, 1, 1]),
        (Epsilon, [Epsilon, Epsilon, Epsilon, Epsilon]),
        (Epsilon, [4 * Epsilon, 0, 0, 0]),
        (1 - Epsilon, [1 - Epsilon, 1 - Epsilon, 1 - Epsilon, 1 - Epsilon]),
        (1 - Epsilon, [1, 1, 1, 1 - 4 * Epsilon]),
    ];

    public static TheoryData<string, string> Data()
    {
        var data = new TheoryData<string, string>();
        foreach (var engine in new[] { HardCaseEngines.Analytic, HardCaseEngines.FullState })
            foreach (var method in new[] { "mc", "qcoin", "mlae", "qss", "qss-planes" })
                data.Add(engine, method);
        return data;
    }

    /// <summary>An estimator at about 240 queries, and M, the most Grover operators any of its flips or runs applies.</summary>
    private static (IMeanEstimator Estimator, int MostIterations) Create(string method) => method switch
    {
        "mc" => (new MonteCarloEstimator(240), 0),
        "qcoin" => (new QCoinEstimator(240, 4), 1 << 3),
        "mlae" => Mlae(new MaximumLikelihoodEstimator(240, MaximumLikelihoodEstimator.DefaultLevels(240))),
        "qss" => (new QssEstimator(7), (1 << 7) - 1),
        _ => (new BitPlaneQssEstimator(QssLookupTable.Exact(4, 4), 8), (1 << 4) - 1),
    };

    private static (IMeanEstimator, int) Mlae(MaximumLikelihoodEstimator mlae) => (mlae, mlae.Iterations.Max());

    private ICoinEngine Engine(string name) => name == HardCaseEngines.Analytic
        ? new AnalyticCoinEngine(new SeededRandom(31))
        : new FullStateCoinEngine(fixture.Engine.Pool, ownsPool: false);

    [Theory]
    [MemberData(nameof(Data))]
    public void EstimatesAtTheEndsStayInRangeAndWithinTolerance(string engineName, string method)
    {
        var trials = engineName == HardCaseEngines.Analytic ? 200 : 3;
        var (estimator, most) = Create(method);
        var items = Means.SelectMany(m => Enumerable.Repeat(m.Values, trials)).ToArray();
        using var engine = Engine(engineName);
        var estimates = estimator.Estimate(items, engine);
        Assert.Equal(items.Length, estimates.Count);
        // Bit planes run P circuits of Q each; the bound is per run, so take the whole budget as Q.
        var q = Math.Min(1, 3 * (2.0 * most + 1) * estimator.Queries * Epsilon);
        for (var k = 0; k < Means.Length; k++)
        {
            var (mean, values) = Means[k];
            var what = $"{engineName}, {estimator.Name}, mean {mean} as [{string.Join(", ", values)}]";
            var slice = estimates.Skip(k * trials).Take(trials).ToArray();
            Assert.All(slice, e => Assert.True(double.IsFinite(e) && e >= 0 && e <= 1, $"{what}: estimate {e}"));
            if (mean is 0 or 1)
            {
                Assert.All(slice, e => Assert.True(e == mean, $"{what}: estimate {e}, expected exactly {mean}"));
                continue;
            }
            var off = slice.Count(e => Math.Abs(e - mean) > 2 * Epsilon);
            var (_, high) = StatisticalBounds.BinomialInterval(q, trials);
            Assert.True(off <= high, $"{what}: {off} of {trials} estimates more than 2e-9 off (allowed {high}, q = {q:0.##e+0}): [{string.Join(", ", slice.Where(e => Math.Abs(e - mean) > 2 * Epsilon).Take(5))}]");
        }
    }
}
