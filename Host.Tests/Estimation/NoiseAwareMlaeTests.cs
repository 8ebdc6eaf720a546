using QuantumRayTracing.Randomness;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Tests.Estimation;

/// <summary>
/// The noise-aware MLAE on noisy direct coins of the analytic engine (<see cref="DepolarizedCoinEngine"/>, fixed seeds) and plain MLAE beside it.
/// Every statistical bound is stated with its false-failure rate; z = 5.73 is the two-sided normal point of 1e-8.
/// </summary>
public class NoiseAwareMlaeTests
{
    private const double Z = 5.73;

    private static double[][] UniformMeans(int count, ulong seed)
    {
        var random = new SeededRandom(seed);
        return Enumerable.Range(0, count).Select(_ => new[] { random.NextDouble() }).ToArray();
    }

    [Fact]
    public void PlainMlaeStillEstimatesFromItsOwnFlipsAlone()
    {
        // The shared flip step must not change plain MLAE: the same requests in the same order, read by MostLikelyAngle.
        var values = UniformMeans(300, 3).Concat([[0.0, 0.0], [1.0, 1.0], [0.25, 0.75, 1.0]]).ToArray();
        foreach (var queries in new long[] { 60, 240, 3200 })
        {
            var mlae = new MaximumLikelihoodEstimator(queries, MaximumLikelihoodEstimator.DefaultLevels(queries));
            var estimates = mlae.Estimate(values, new AnalyticCoinEngine(new SeededRandom(7)));
            var engine = new AnalyticCoinEngine(new SeededRandom(7));
            var requests = values.SelectMany(v => mlae.Iterations.Select((m, l) => new CoinRequest(CoinKind.Mean, CoinValues.MeanCoin(v), m, mlae.Flips[l]))).ToArray();
            var heads = engine.FlipCoins(requests);
            for (var j = 0; j < values.Length; j++)
            {
                var observed = mlae.Iterations.Select((m, l) => (2 * m + 1, heads[j * mlae.Iterations.Length + l], mlae.Flips[l])).ToArray();
                var expected = Math.Clamp(Math.Pow(Math.Sin(MaximumLikelihoodEstimator.MostLikelyAngle(observed)), 2), 0, 1);
                Assert.Equal(expected, estimates[j]);
            }
        }
    }

    [Fact]
    public void WithoutNoiseReadsAlmostEveryPixelAsPlainMlae()
    {
        // On noiseless flips the likelihood-ratio test keeps the plain fit unless the decay wins by 5.41 (its 1% point,
        // asymptotically; the decay's prior only lowers the rate). On the fixed schedule, so that both read the very same
        // flips. Bound: at most 5% of 1000 means read differently: Binomial(1000, 0.01) exceeds 50 with probability below
        // 1e-19, and Binomial(1000, 0.02) with probability 3e-9, so a 1% test fails this with probability below 1e-8 even if
        // its small-sample rate were twice that.
        var values = UniformMeans(1000, 5);
        foreach (var queries in new long[] { 240, 960 })
        {
            var levels = MaximumLikelihoodEstimator.DefaultLevels(queries);
            var plain = new MaximumLikelihoodEstimator(queries, levels).Estimate(values, new AnalyticCoinEngine(new SeededRandom(9)));
            var aware = new NoiseAwareMaximumLikelihoodEstimator(queries, levels, adaptive: false).Estimate(values, new AnalyticCoinEngine(new SeededRandom(9)));
            var differing = plain.Zip(aware).Count(p => p.First != p.Second);
            Assert.True(differing <= 50, $"{queries} queries: {differing} of 1000 means read differently from plain MLAE");
        }
    }

    [Fact]
    public void AdaptiveScheduleWithoutNoiseMakesPlainMlaesFlipsAndSpendsTheBudgetExactly()
    {
        // Without noise the survey finds no decay for almost every mean, and the rest of the budget goes to plain MLAE's
        // remaining levels: the same levels and flips as plain MLAE. Bound as above: at most 5% of 1000 means get another
        // plan (false failure below 1e-8 for a test of rate up to 2%). Every mean's flips cost exactly the budget, always.
        var values = UniformMeans(1000, 21);
        foreach (var queries in new long[] { 240, 3200 })
        {
            var aware = new NoiseAwareMaximumLikelihoodEstimator(queries, MaximumLikelihoodEstimator.DefaultLevels(queries));
            Assert.InRange(aware.SurveyLevels, 2, aware.Iterations.Length - 1);
            var plain = aware.Iterations.Zip(aware.Flips).ToArray();
            var observed = aware.Observe(values, new AnalyticCoinEngine(new SeededRandom(23)));
            Assert.All(observed, levels => Assert.Equal(queries, levels.Sum(l => (1 + 2L * l.Iterations) * l.Flips)));
            var other = observed.Count(levels => !levels.Select(l => (l.Iterations, l.Flips)).SequenceEqual(plain));
            Assert.True(other <= 50, $"{queries} queries: {other} of 1000 means got flips other than plain MLAE's");
        }
    }

    [Theory]
    [InlineData(0.1)]
    [InlineData(0.03)]
    public void AdaptiveScheduleSpendsTheRestWhereInformationPerQueryPeaks(double decay)
    {
        // A level of k = 2m+1 queries per flip gives information about θ about k²Φ² = k²e^(−γk) per flip, so k·e^(−γk) per
        // query: largest at k = 1/γ. The plan for the rest of 3200 queries, after a survey whose heads are their expected
        // counts at f = 0.3 and decay γ, must pick one level with k within a factor 2 of 1/γ (the phase of each fringe moves
        // the exact optimum, not by that much) and spend the rest exactly. A plan that ignored the decay would pick the
        // deepest level it can afford (k ≈ 3200/2 − …), far above 2/γ.
        const long queries = 3200;
        var aware = new NoiseAwareMaximumLikelihoodEstimator(queries, MaximumLikelihoodEstimator.DefaultLevels(queries));
        var theta = Math.Asin(Math.Sqrt(0.3));
        var survey = Enumerable.Range(0, aware.SurveyLevels).Select(l =>
        {
            var (m, n) = (aware.Iterations[l], aware.Flips[l]);
            return new MlaeLevel(m, (int)Math.Round(n * NoiseAwareMaximumLikelihoodEstimator.HeadProbability(theta, decay, m)), n);
        }).ToArray();
        var rest = queries - survey.Sum(l => (1 + 2L * l.Iterations) * l.Flips);
        var plan = aware.PlanRest(survey, rest);
        Assert.Equal(rest, plan.Sum(l => (1 + 2L * l.Iterations) * l.Flips));
        var amplified = plan.Where(l => l.Iterations > 0).ToArray();
        Assert.Single(amplified);
        Assert.InRange(2 * amplified[0].Iterations + 1, 0.5 / decay, 2 / decay);
    }

    [Fact]
    public void AdaptiveScheduleErrsLessThanTheFixedOneWhereNoiseFlattensTheDeepLevels()
    {
        // Decay 0.1, 3200 queries: the fixed schedule spends about two thirds of its queries on levels m = 26, 38, 58 with
        // Φ below 0.08, the adaptive one on a level near m = 5. Measured (seeds 11 to 13, 200 trials per mean): the fixed
        // schedule's mean absolute error is 1.1x to 1.8x the adaptive one's, 1.45x pooled. Bound: pooled over f = 0.2, 0.35,
        // 0.8 with 400 trials each, the adaptive error is at most the fixed one's. These errors are heavy-tailed (standard
        // deviation of the absolute error about 2.5x its mean), so each pooled mean absolute error has a relative standard
        // error near 7% and their ratio near 10%: ln 1.45 is 3.6 of those standard errors, so a true ratio of 1.45 falls below
        // 1 with probability about 1.5e-4 (fewer trials would raise that past 1e-3, so the 400 stay). The adaptive
        // estimates are also unbiased within Z standard errors at each mean (false failure 1e-8 each). And the same seed
        // gives the same estimates.
        const long queries = 3200;
        const double decay = 0.1;
        const int trials = 400;
        var levels = MaximumLikelihoodEstimator.DefaultLevels(queries);
        var (fixedErrors, adaptiveErrors) = (new List<double>(), new List<double>());
        foreach (var (mean, seed) in new[] { (0.2, 31UL), (0.35, 32UL), (0.8, 33UL) })
        {
            var values = Enumerable.Repeat(new[] { mean }, trials).ToArray();
            var fixedSchedule = new NoiseAwareMaximumLikelihoodEstimator(queries, levels, adaptive: false).Estimate(values, DepolarizedCoinEngine.Create(new SeededRandom(seed), decay));
            var adaptive = new NoiseAwareMaximumLikelihoodEstimator(queries, levels).Estimate(values, DepolarizedCoinEngine.Create(new SeededRandom(seed), decay));
            if (mean == 0.2)
            {
                // Reproducibility needs one mean, not three: a fortieth of the trials, run again on the same seed.
                var few = values[..(trials / 40)];
                var first = new NoiseAwareMaximumLikelihoodEstimator(queries, levels).Estimate(few, DepolarizedCoinEngine.Create(new SeededRandom(seed + 100), decay));
                var again = new NoiseAwareMaximumLikelihoodEstimator(queries, levels).Estimate(few, DepolarizedCoinEngine.Create(new SeededRandom(seed + 100), decay));
                Assert.Equal(first, again);
            }
            fixedErrors.AddRange(fixedSchedule.Select(e => Math.Abs(e - mean)));
            adaptiveErrors.AddRange(adaptive.Select(e => Math.Abs(e - mean)));
            var average = adaptive.Average();
            var sd = Math.Sqrt(adaptive.Sum(e => (e - average) * (e - average)) / (trials - 1));
            Assert.True(Math.Abs(average - mean) <= Z * sd / Math.Sqrt(trials), $"f = {mean}: adaptive mean estimate {average:0.00000}, standard error {sd / Math.Sqrt(trials):0.00000}");
        }
        Assert.True(adaptiveErrors.Average() <= fixedErrors.Average(), $"adaptive {adaptiveErrors.Average():0.00000} against fixed {fixedErrors.Average():0.00000}");
    }

    [Fact]
    public void RecoversAKnownMeanAndDecayFromSyntheticFlips()
    {
        // Many flips per level, so the Cramér–Rao bound is the error scale: over 60 trials the mean of the estimates lies
        // within Z·σ/√60 (+ a bias allowance of σ/4 for a finite sample) of the truth, for the mean and for the decay,
        // with σ from the Fisher information; false-failure below 1e-8 each for an efficient, unbiased estimator.
        const double mean = 0.3, decay = 0.05;
        const int trials = 60, flips = 3000;
        int[] iterations = [0, 1, 2, 3, 5, 8, 11, 17];
        var levels = iterations.Select(m => (m, flips)).ToArray();
        var theta = Math.Asin(Math.Sqrt(mean));
        var random = new SeededRandom(13);
        var (means, decays) = (new double[trials], new double[trials]);
        for (var t = 0; t < trials; t++)
        {
            var observed = iterations.Select(m =>
            {
                var p = NoiseAwareMaximumLikelihoodEstimator.HeadProbability(theta, decay, m);
                return new MlaeLevel(m, Enumerable.Range(0, flips).Count(_ => random.NextDouble() < p), flips);
            }).ToArray();
            var (angle, fitted) = NoiseAwareMaximumLikelihoodEstimator.MostLikely(observed);
            (means[t], decays[t]) = (Math.Pow(Math.Sin(angle), 2), fitted);
        }
        var sigmaMean = MlaeFisherInformation.StandardError(mean, decay, levels);
        var sigmaDecay = MlaeFisherInformation.DecayStandardError(mean, decay, levels);
        Assert.InRange(means.Average(), mean - Z * sigmaMean / Math.Sqrt(trials) - sigmaMean / 4, mean + Z * sigmaMean / Math.Sqrt(trials) + sigmaMean / 4);
        Assert.InRange(decays.Average(), decay - Z * sigmaDecay / Math.Sqrt(trials) - sigmaDecay / 4, decay + Z * sigmaDecay / Math.Sqrt(trials) + sigmaDecay / 4);
        // And the spread is the predicted one: the root mean square error within 0.6x..1.6x of σ (a chi-square with 60
        // degrees of freedom leaves that range with probability below 1e-8 at the true σ; the MLE is efficient here).
        var rms = Math.Sqrt(means.Average(m => (m - mean) * (m - mean)));
        Assert.InRange(rms, 0.6 * sigmaMean, 1.6 * sigmaMean);
    }

    [Fact]
    public void PlainMlaeErrsOnNoisyFlipsWhereTheNoiseAwareOneDoesNot()
    {
        // Decay 0.1 per Grover operator, 960 queries (levels up to m = 17, where Φ = e^(−γ(m+½)) = 0.17). Plain MLAE reads the
        // flattened levels as a wrong angle. Measured on 200 trials per mean (seeds fixed): plain's mean absolute error is 4.9x
        // and 5.4x the noise-aware one's at f = 0.2 and 0.8 (2.3x at 0.6; 1.5x at 0.45, near the anomalous ½). Bounds: the
        // noise-aware estimates are unbiased within Z standard errors of their mean (false failure 1e-8 each), and plain's mean
        // absolute error is at least 2x theirs: each mean absolute error over 200 trials has a relative standard error under
        // 10% here, so a ratio near 5 sits more than 4 standard errors above 2 (false failure below 1e-4 each). Dropping the
        // decay from the likelihood makes the two estimators one, and the ratio 1.
        const long queries = 960;
        const double decay = 0.1;
        const int trials = 200;
        var levels = MaximumLikelihoodEstimator.DefaultLevels(queries);
        foreach (var mean in new[] { 0.2, 0.8 })
        {
            var values = Enumerable.Repeat(new[] { mean }, trials).ToArray();
            var plain = new MaximumLikelihoodEstimator(queries, levels).Estimate(values, DepolarizedCoinEngine.Create(new SeededRandom(11), decay));
            var aware = new NoiseAwareMaximumLikelihoodEstimator(queries, levels).Estimate(values, DepolarizedCoinEngine.Create(new SeededRandom(11), decay));
            var average = aware.Average();
            var sd = Math.Sqrt(aware.Sum(e => (e - average) * (e - average)) / (trials - 1));
            Assert.True(Math.Abs(average - mean) <= Z * sd / Math.Sqrt(trials), $"f = {mean}: noise-aware mean estimate {average:0.00000}, standard error {sd / Math.Sqrt(trials):0.00000}");
            var (plainError, awareError) = (plain.Average(e => Math.Abs(e - mean)), aware.Average(e => Math.Abs(e - mean)));
            Assert.True(plainError >= 2 * awareError, $"f = {mean}: plain MLAE's mean absolute error {plainError:0.00000} against the noise-aware {awareError:0.00000}");
        }
    }

    [Theory]
    [InlineData(0.0)]
    [InlineData(0.05)]
    [InlineData(0.5)]
    public void MeansAtAndNearTheEndsStayFiniteAndInRange(double decay)
    {
        const double epsilon = 1e-9;
        double[][] values = [[0.0], [1.0], [epsilon], [1 - epsilon], [0, 0, 0, 4 * epsilon], [1, 1, 1, 1 - 4 * epsilon], [0, 1]];
        foreach (var queries in new long[] { 1, 240, 3200 })
        {
            var estimator = new NoiseAwareMaximumLikelihoodEstimator(queries, MaximumLikelihoodEstimator.DefaultLevels(queries));
            var inputs = values.SelectMany(v => Enumerable.Repeat(v, 50)).ToArray();
            var estimates = estimator.Estimate(inputs, DepolarizedCoinEngine.Create(new SeededRandom(19), decay));
            Assert.All(estimates, e => Assert.True(double.IsFinite(e) && e is >= 0 and <= 1, $"{estimator.Name}, decay {decay}: estimate {e}"));
            if (decay == 0)
            {
                // Without noise a mean of 0 shows no head and a mean of 1 no tail: both are exact.
                Assert.All(estimates.Take(50), e => Assert.Equal(0, e));
                Assert.All(estimates.Skip(50).Take(50), e => Assert.Equal(1, e));
            }
        }
    }

    [Fact]
    public void FisherInformationSaturatesUnderNoiseAndFindsItsAnomalousMeans()
    {
        var mlae = new MaximumLikelihoodEstimator(3200, MaximumLikelihoodEstimator.DefaultLevels(3200));
        var levels = MlaeFisherInformation.Levels(mlae.Iterations, mlae.Flips);
        // Without noise, every level adds (2m+1)²-weighted information; under noise the deep levels add little.
        var ideal = MlaeFisherInformation.AverageMeanAbsoluteError(0, levels, decayKnown: true);
        var noisy = MlaeFisherInformation.AverageMeanAbsoluteError(0.1, levels);
        Assert.True(noisy > 5 * ideal, $"predicted error {noisy} under decay 0.1 against {ideal} without noise");
        // The same flips with the deep levels left out predict almost the same error under noise: they carry nothing.
        var shallow = levels.Where(l => l.Iterations <= 17).ToArray();
        var shallowError = MlaeFisherInformation.AverageMeanAbsoluteError(0.1, shallow);
        Assert.InRange(noisy / shallowError, 0.9, 1.0 + 1e-9);
        // f = ½ (θ = π/4) is anomalous under noise: every level reads ½ whatever γ, so nearby θ and γ trade off and
        // fitting the decay costs at least 1.5x in σ. Away from such fractions (f = 0.1) fitting it costs little.
        var anomalous = MlaeFisherInformation.AnomalousMeans(0.03, levels);
        Assert.Contains(anomalous, f => Math.Abs(f - 0.5) < 1e-3);
        Assert.True(MlaeFisherInformation.StandardError(0.5004, 0.03, levels) > 1.5 * MlaeFisherInformation.StandardError(0.5004, 0.03, levels, decayKnown: true));
        Assert.DoesNotContain(anomalous, f => Math.Abs(f - 0.1) < 0.005);
    }
}
