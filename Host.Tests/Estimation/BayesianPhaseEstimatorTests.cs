using QuantumRayTracing.Randomness;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Tests.Estimation;

/// <summary>
/// QSS with single-ancilla Bayesian phase estimation (qss-bayes) on the analytic engine, fixed seeds. The shot's formula is
/// checked against the circuit multiplied out; the engine's draws against the formula; the estimator against QSS's long
/// tail; a likelihood with the wrong fringe (cos(kθ) where the circuit gives cos(2kθ)) against the error bound it must miss.
/// Its error against Monte Carlo and its slope are checked beside the other adaptive estimators in <see cref="AmplitudeEstimatorTests"/>.
/// </summary>
public class BayesianPhaseEstimatorTests
{
    /// <summary>
    /// The circuit on one coin qubit (good = |1⟩), multiplied out: A = R_y(2θ), Q = A(2|0⟩⟨0| − I)A†·Z; ancilla |+⟩, coin A|0⟩,
    /// controlled Q^k, phase β on the ancilla's |1⟩, H, ancilla read 0. Its probability must be ½ + ½·cos(2kθ)·cos β, and at
    /// β = 0 what <see cref="CoinProbability.AncillaZero"/> gives: so β only scales the contrast, and 0 is the best phase.
    /// </summary>
    [Fact]
    public void TheShotsProbabilityIsThatOfTheCircuit()
    {
        foreach (var f in new[] { 0.0, 0.03, 0.2, 0.5, 0.77, 1.0 })
            foreach (var k in new[] { 0, 1, 2, 3, 7, 20 })
                foreach (var beta in new[] { 0.0, 0.4, Math.PI / 2, 2.5 })
                {
                    var theta = Math.Asin(Math.Sqrt(f));
                    var (c, s) = (Math.Cos(theta), Math.Sin(theta));
                    double[] psi = [c, s];
                    // Q = A (2|0⟩⟨0| − I) A† Z, with A = [[c, −s], [s, c]]: the reflection about A|0⟩ after the sign flip of good.
                    double[,] q = { { 2 * c * c - 1, -(2 * c * s) }, { 2 * c * s, 1 - 2 * s * s } };
                    var branch = (double[])psi.Clone();
                    for (var i = 0; i < k; i++) branch = [q[0, 0] * branch[0] + q[0, 1] * branch[1], q[1, 0] * branch[0] + q[1, 1] * branch[1]];
                    // Ancilla after H: (|0⟩(ψ + e^{iβ}Q^kψ) + |1⟩(ψ − e^{iβ}Q^kψ)) / 2; P(0) = |ψ + e^{iβ}Q^kψ|² / 4.
                    var zero = 0.0;
                    for (var j = 0; j < 2; j++)
                    {
                        var (re, im) = (psi[j] + Math.Cos(beta) * branch[j], Math.Sin(beta) * branch[j]);
                        zero += (re * re + im * im) / 4;
                    }
                    Assert.Equal(0.5 + 0.5 * Math.Cos(2 * k * theta) * Math.Cos(beta), zero, 12);
                    if (beta == 0) Assert.Equal(CoinProbability.AncillaZero(Math.Sqrt(f), k), zero, 12);
                }
    }

    /// <summary>
    /// 40,000 shots per (f, k) on the analytic engine against cos²(kθ): the zeros' standard deviation is at most 100, so a
    /// bound of 5 of them fails falsely with probability below 1e-5 over the 20 cases; a draw at the wrong fringe
    /// (cos²(2kθ) or cos²(kθ/2)) is off by hundreds of standard deviations at these points.
    /// </summary>
    [Fact]
    public void TheAnalyticEngineDrawsTheShotsProbability()
    {
        const int shots = 40_000;
        var means = new[] { 0.05, 0.3, 0.5, 0.62, 0.9 };
        var powers = new[] { 1, 2, 5, 13 };
        var requests = means.SelectMany(f => powers.Select(k => new AncillaPhaseRequest([Math.Sqrt(f)], k, shots))).ToArray();
        var zeros = new AnalyticCoinEngine(new SeededRandom(17)).CountAncillaZeros(requests);
        for (var i = 0; i < requests.Length; i++)
        {
            var p = CoinProbability.AncillaZero(requests[i].Amplitudes[0], requests[i].Power);
            var sd = Math.Sqrt(shots * p * (1 - p));
            Assert.True(Math.Abs(zeros[i] - shots * p) <= 5 * Math.Max(sd, 1), $"f = {requests[i].Amplitudes[0] * requests[i].Amplitudes[0]}, k = {requests[i].Power}: {zeros[i]} zeros, expected {shots * p:0}");
        }
    }

    private static double[][] RandomMeans(int count, ulong seed)
    {
        var random = new SeededRandom(seed);
        return Enumerable.Range(0, count).Select(_ => new[] { random.NextDouble() }).ToArray();
    }

    private static double[] SortedErrors(IMeanEstimator estimator, double[][] means, ulong seed)
    {
        var estimates = estimator.Estimate(means, new AnalyticCoinEngine(new SeededRandom(seed)));
        return [.. estimates.Select((e, j) => Math.Abs(e - means[j][0])).Order()];
    }

    private static double TailShare(double[] sorted)
    {
        var median = sorted[sorted.Length / 2];
        return sorted.Count(e => e > 3 * median) / (double)sorted.Length;
    }

    /// <summary>
    /// The point of the method: fewer estimates far from the rest than QSS at the same queries (QSS t = 7 and 9: 255 and
    /// 1,023). On 800 means the measured shares were 7.8% against 12.1% and 5.9% against 11.6%. Each share is a binomial
    /// proportion, so over n means their difference has standard error √((p₁(1 − p₁) + p₂(1 − p₂)) / n): 0.0094 at t = 7
    /// over 2,000 means against a gap of 4.3 points, 0.0126 at t = 9 over 1,000 means against 5.7 points, both 4.5 standard
    /// errors (false failure about 3e-6 per budget). A Bayesian estimator no better than QSS (gap 0) fails with probability ½.
    /// </summary>
    [Theory]
    [InlineData(7, 2000)]
    [InlineData(9, 1000)]
    public void ItsLongTailIsShorterThanQsss(int counterBits, int count)
    {
        var means = RandomMeans(count, 61);
        var queries = QssRequest.QueriesPerRun(counterBits);
        var (bayes, qss) = (TailShare(SortedErrors(new BayesianPhaseEstimator(queries), means, 7)), TailShare(SortedErrors(new QssEstimator(counterBits), means, 7)));
        Assert.True(bayes < qss, $"{queries} queries: share above 3x the median error {bayes:0.000} with Bayesian phase estimation, {qss:0.000} with QSS");
    }

    /// <summary>
    /// Negative control: a likelihood reading the shot as ½ + ½·cos(kθ) (the eigenphase's factor 2 lost) puts the posterior on
    /// the wrong angle. The right likelihood errs by about 0.0034 on average at 960 queries (<see cref="AmplitudeEstimatorTests"/>
    /// bounds it below 0.4 of Monte Carlo's 0.0103); the wrong one must miss that bound, and it misses it by far (about 0.4, a
    /// hundred times the bound). 100 means suffice: one mean's error lies in [0, 1], so their average falls to the bound only 0.39
    /// below its expectation, with probability below exp(−2 · 100 · 0.39²) ≈ 6e-14 (Hoeffding).
    /// </summary>
    [Fact]
    public void AWrongFringeFailsTheErrorBound()
    {
        var means = RandomMeans(100, 31);
        var wrong = new BayesianPhaseEstimator(960, new PosteriorFringe(0.5, 0, Math.PI / 2, 1));
        var error = SortedErrors(wrong, means, 5).Average();
        Assert.True(error > 0.4 * 0.0103, $"with the wrong fringe: mean error {error:0.00000}");
    }

    [Fact]
    public void TheEnginesWithoutTheShotRefuseIt()
    {
        AncillaPhaseRequest[] request = [new([0.5], 1, 1)];
        Assert.Throws<ArgumentException>(() => new DirectCoinEngine(new AnalyticCoinEngine(new SeededRandom(1))).CountAncillaZeros(request));
        Assert.Throws<ArgumentException>(() => new AnalyticCoinEngine(new SeededRandom(1), QuantumRayTracing.Noise.NoiseModel.Depolarizing(0.01)).CountAncillaZeros(request));
    }
}
