using QuantumRayTracing.Randomness;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Tests.Estimation;

/// <summary>
/// IQAE, FAE, BAE, power-law AE and QSS with Bayesian phase estimation (qss-bayes) on the analytic engine, fixed seeds, 800 uniform random means (one subpixel each; the Monte Carlo margins use the first 400).
/// Each bound is stated against what a wrong estimator would show: Monte Carlo's exact expected error at the same
/// queries (the quantum estimators must beat it by a margin), and the fitted log-log slope of the mean error between
/// 400 and 3,200 queries (−0.5 is Monte Carlo's scaling, −1 Heisenberg's). The standard error of an n-mean average
/// error is about 0.8/√n of it (the absolute errors' standard deviation is about 0.8 of their mean): 3% over the 800 means
/// of the slopes, so their bounds, each at least 15% from the measured value, are over 5 standard errors (false failure
/// below 1e-6 per check); 4% over the first 400 means, on which the Monte Carlo margins are checked, whose bounds are at
/// least 29% above the measured ratios (FAE's median 0.58 against 0.75), so ln 1.29 / 0.04 = 6.4 standard errors (false
/// failure below 1e-9 per check). The negative controls show the checks fail on wrong variants: power-law AE with β = 1 (every flip at m = 1, a
/// classical schedule) misses the slope bound, and IQAE without its bias fix shows the bias at a mean where it is known
/// to be large.
/// </summary>
public class AmplitudeEstimatorTests
{
    private const int Trials = 800;

    private static readonly double[][] Means = RandomMeans(Trials, 31);

    private static double[][] RandomMeans(int count, ulong seed)
    {
        var random = new SeededRandom(seed);
        return Enumerable.Range(0, count).Select(_ => new[] { random.NextDouble() }).ToArray();
    }

    private static IMeanEstimator Create(string method, long queries) => method switch
    {
        "iqae" => new IterativeAmplitudeEstimator(queries),
        "iqae-biased" => new IterativeAmplitudeEstimator(queries, rerunLastRound: false),
        "fae" => new FasterAmplitudeEstimator(queries),
        "bae" => new BayesianAmplitudeEstimator(queries),
        "powerlaw" => new PowerLawAmplitudeEstimator(queries),
        "qss-bayes" => new BayesianPhaseEstimator(queries),
        "powerlaw-classical" => new PowerLawAmplitudeEstimator(queries, beta: 1),
        _ => throw new ArgumentException(method),
    };

    // FAE's mean error is dominated by rare rounds that resolve the wrong period (its mean moved by half between seeds in
    // the measurements, docs/supersampling.md, while its median held), so it is held to its median error, whose standard error is a few per cent.
    private static double Error(string method, long queries, int count = Trials)
    {
        var means = Means[..count];
        var estimates = Create(method, queries).Estimate(means, new AnalyticCoinEngine(new SeededRandom(5)));
        var errors = estimates.Select((e, j) => Math.Abs(e - means[j][0])).Order().ToArray();
        return method == "fae" ? errors[errors.Length / 2] : errors.Average();
    }

    /// <summary>Monte Carlo's exact expected error E|X/Q − f|, X ~ Binomial(Q, f), averaged over the test's means.</summary>
    private static double MonteCarloError(int queries, int count) => Means[..count].Average(m =>
    {
        var binomial = new MathNet.Numerics.Distributions.Binomial(m[0], queries);
        return Enumerable.Range(0, queries + 1).Sum(x => binomial.Probability(x) * Math.Abs((double)x / queries - m[0]));
    });

    /// <summary>Monte Carlo's median error over the test's means: one seeded Monte Carlo estimate per mean.</summary>
    private static double MonteCarloMedianError(int queries, int count)
    {
        var means = Means[..count];
        var estimates = new MonteCarloEstimator(queries).Estimate(means, new AnalyticCoinEngine(new SeededRandom(77)));
        var errors = estimates.Select((e, j) => Math.Abs(e - means[j][0])).Order().ToArray();
        return errors[errors.Length / 2];
    }

    // Measured ratios to Monte Carlo on these means: iqae 0.42 and bae 0.16 at 960 queries, powerlaw 0.21; fae's median 0.58 at 3,200;
    // qss-bayes 0.57 at 240 and 0.33 at 960.
    [Theory]
    [InlineData("qss-bayes", 240, 0.75)]
    [InlineData("qss-bayes", 960, 0.45)]
    [InlineData("iqae", 960, 0.6)]
    [InlineData("bae", 960, 0.4)]
    [InlineData("powerlaw", 960, 0.4)]
    [InlineData("fae", 3200, 0.75)]
    public void BeatsMonteCarloByAMargin(string method, int queries, double ratio)
    {
        const int count = Trials / 2;
        var (error, monteCarlo) = (Error(method, queries, count), method == "fae" ? MonteCarloMedianError(queries, count) : MonteCarloError(queries, count));
        Assert.True(error < ratio * monteCarlo, $"{method} at {queries} queries: mean error {error:0.00000}, Monte Carlo's {monteCarlo:0.00000}, bound {ratio} of it");
    }

    // Heisenberg scaling is slope −1; the bound −0.8 leaves room for the constant's drift, and Monte Carlo's −0.5 is far outside.
    // FAE (its median error) is held to −0.7.
    [Theory]
    [InlineData("iqae", -0.8)]
    [InlineData("bae", -0.8)]
    [InlineData("qss-bayes", -0.8)]
    [InlineData("powerlaw", -0.8)]
    [InlineData("fae", -0.7)]
    public void ErrorFallsAboutAsOneOverQueries(string method, double bound)
    {
        var slope = Slope(method);
        Assert.True(slope < bound, $"{method}: fitted slope {slope:0.000} between 400 and 3,200 queries, bound {bound}");
    }

    [Fact]
    public void AClassicalScheduleFailsTheSlopeBound()
    {
        // β = 1 puts every flip at m = 1: a Monte Carlo estimate of sin²(3θ), whose error falls as queries^−½.
        var slope = Slope("powerlaw-classical");
        Assert.True(slope > -0.65, $"power-law with β = 1: fitted slope {slope:0.000}");
    }

    private static double Slope(string method) => Math.Log(Error(method, 3200) / Error(method, 400)) / Math.Log(8);

    /// <summary>
    /// At f = 0.31 and 240 queries the original IQAE estimate (the last interval's middle) is pulled towards ½ by about 0.009
    /// (measured over the means 0.01..0.99, docs/supersampling.md: it is largest near 0.31 and 0.68); with the last round rerun at
    /// a fixed k the bias is about 0.001. Over 4,000 trials the standard error of the mean signed error is about 0.0005, so the
    /// bounds 0.005 and 0.003 are at least 4 standard errors from the measured values (false failure below 1e-4).
    /// </summary>
    [Fact]
    public void TheRerunLastRoundRemovesIqaesBias()
    {
        const double f = 0.31;
        var values = Enumerable.Repeat(new[] { f }, 4000).ToArray();
        double Bias(bool fix) => new IterativeAmplitudeEstimator(240, rerunLastRound: fix)
            .Estimate(values, new AnalyticCoinEngine(new SeededRandom(41))).Average() - f;
        var (biased, fixedBias) = (Bias(false), Bias(true));
        Assert.True(biased > 0.005, $"without the fix: mean signed error {biased:0.00000}");
        Assert.True(Math.Abs(fixedBias) < 0.003, $"with the fix: mean signed error {fixedBias:0.00000}");
    }

    [Fact]
    public void NoItemSpendsMoreThanTheBudget()
    {
        var inputs = RandomMeans(60, 8).Concat([[0.0], [1.0], [1e-9], [1 - 1e-9], [0.5], [0.25], [0.75]]).ToArray();
        foreach (var queries in new long[] { 3, 4, 15, 16, 61, 240, 997, 3200 })
            foreach (var estimator in new AdaptiveMeanEstimator[]
            {
                new IterativeAmplitudeEstimator(queries), new IterativeAmplitudeEstimator(queries, 4, BinomialIntervalKind.Chernoff, rerunLastRound: false),
                new FasterAmplitudeEstimator(queries), new BayesianAmplitudeEstimator(queries), new BayesianPhaseEstimator(queries),
            })
            {
                // The engine counts what it is asked for, independently of the estimator's own tally.
                var engine = new QueryCountingEngine(new AnalyticCoinEngine(new SeededRandom(3)));
                var (estimates, spent) = estimator.EstimateCounted(inputs, engine);
                Assert.All(spent, s => Assert.InRange(s.Queries, 1, queries));
                Assert.All(spent, s => Assert.InRange(s.GroverOperators, 0, (s.Queries - 1) / 2));
                Assert.Equal(engine.Queries, spent.Sum(s => s.Queries));
                Assert.All(estimates, e => Assert.InRange(e, 0, 1));
            }
        // Power-law AE spends its budget exactly.
        foreach (var queries in new long[] { 1, 15, 240, 3200 })
            Assert.Equal(queries, new PowerLawAmplitudeEstimator(queries).Levels.Sum(l => (long)l.Flips * (1 + 2 * l.Iterations)));
    }

    [Fact]
    public void SameSeedGivesSameEstimates()
    {
        var inputs = Enumerable.Range(0, 40).Select(k => new[] { k / 39.0, 1 - k / 39.0, 0.3 }).ToArray();
        foreach (var method in new[] { "iqae", "fae", "bae", "powerlaw", "qss-bayes" })
            Assert.Equal(Create(method, 240).Estimate(inputs, new AnalyticCoinEngine(new SeededRandom(4))),
                Create(method, 240).Estimate(inputs, new AnalyticCoinEngine(new SeededRandom(4))));
    }

    /// <summary>
    /// On the direct single-qubit coin (the QCoin paper's hardware coin) every estimator sees the same head probabilities as on
    /// the mean coin, FAE's rescaled coin f/4 included, so with the same seed the analytic engine gives the same estimates.
    /// </summary>
    [Fact]
    public void TheDirectCoinGivesTheSameEstimates()
    {
        var inputs = Enumerable.Range(0, 30).Select(k => new[] { k / 29.0, 0.5, 1 - k / 29.0, 0.2 }).ToArray();
        foreach (var method in new[] { "iqae", "fae", "bae", "powerlaw" })
            Assert.Equal(Create(method, 240).Estimate(inputs, new AnalyticCoinEngine(new SeededRandom(9))),
                Create(method, 240).Estimate(inputs, new DirectCoinEngine(new AnalyticCoinEngine(new SeededRandom(9)))));
    }

    /// <summary>IQAE's next power keeps the scaled interval inside one half-period and at least doubles K, or keeps the current k.</summary>
    [Fact]
    public void IqaesNextPowerKeepsTheIntervalInOneHalfPeriod()
    {
        var random = new SeededRandom(12);
        for (var trial = 0; trial < 2000; trial++)
        {
            var low = random.NextDouble() * Math.PI / 2;
            var high = Math.Min(Math.PI / 2, low + Math.Pow(10, -4 * random.NextDouble()) * 0.5);
            var current = random.NextInt(4);
            var (k, upper) = IterativeAmplitudeEstimator.NextPower(low, high, current, true, 100_000);
            if (k == current) continue;
            Assert.True(4 * k + 2 >= 2 * (4 * current + 2), $"k {k} after {current}");
            var factor = 4.0 * k + 2;
            var (a, b) = (factor * low % (2 * Math.PI), factor * high % (2 * Math.PI));
            Assert.True(a <= b + 1e-9, $"[{low}, {high}] at K = {factor} wraps");
            if (upper) Assert.True(b <= Math.PI + 1e-9, $"[{low}, {high}] at K = {factor}: {a}..{b} not in [0, π]");
            else Assert.True(a >= Math.PI - 1e-9, $"[{low}, {high}] at K = {factor}: {a}..{b} not in [π, 2π]");
        }
    }
}
