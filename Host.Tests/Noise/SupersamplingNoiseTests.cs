using QuantumRayTracing.Noise;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;
using QuantumRayTracing.Tests.Statistics;

namespace QuantumRayTracing.Tests.Noise;

/// <summary>The analytic side of the supersampling noise model: no bridge, seeded.</summary>
public class SupersamplingNoiseTests
{
    private static readonly double[] Mean = CoinValues.MeanCoin([0.1, 0.5, 0.3, 0.9]);

    private static readonly double[] Shifted = CoinValues.Shifted([0.3, 0.5, 0.2, 0.6], 0.2);

    private static readonly CoinRequest[] Coins =
    [
        new(CoinKind.Mean, Mean, 0, 300),
        new(CoinKind.Mean, Mean, 2, 300),
        new(CoinKind.Shifted, Shifted, 1, 300),
        new(CoinKind.Direct, [Math.Sqrt(0.1)], 4, 300),
        new(CoinKind.Mean, [1.0, 1.0], 3, 50),
        new(CoinKind.Mean, [0.0, 0.0, 0.0], 2, 50),
    ];

    private static readonly QssRequest[] Readouts = [new(Mean, 3, 200), new(CoinValues.MeanCoin([1.0, 0.0, 1.0]), 4, 200)];

    [Fact]
    public void NoiselessEngineDrawsExactlyAsBefore()
    {
        // The ideal model, given or not, and a zero rate take the exact path draw for draw: same seed, same outcomes.
        var plain = new AnalyticCoinEngine(new SeededRandom(11));
        foreach (var noise in new[] { NoiseModel.None, NoiseModel.Depolarizing(0) })
        {
            var other = new AnalyticCoinEngine(new SeededRandom(11), noise);
            var reference = new AnalyticCoinEngine(new SeededRandom(11));
            Assert.Equal(reference.FlipCoins(Coins), other.FlipCoins(Coins));
            Assert.Equal(reference.ReadCounters(Readouts), other.ReadCounters(Readouts));
        }
        // And it is still the exact distribution: the certain coins stay certain.
        var heads = plain.FlipCoins(Coins);
        Assert.Equal(50, heads[4]);
        Assert.Equal(0, heads[5]);
    }

    [Fact]
    public void AnalyticEngineRefusesQubitLoss() =>
        Assert.Throws<ArgumentException>(() => new AnalyticCoinEngine(new SeededRandom(1), new NoiseModel(0, 0, 0, 0.01)));

    [Theory]
    [InlineData(CoinKind.Mean, 0)]
    [InlineData(CoinKind.Mean, 2)]
    [InlineData(CoinKind.Shifted, 1)]
    [InlineData(CoinKind.Shifted, 2)]
    [InlineData(CoinKind.Direct, 4)]
    public void HeadProbabilityMovesMonotonicallyFromTheIdealTowardsTheMixedShare(CoinKind kind, int iterations)
    {
        var amplitudes = kind switch { CoinKind.Shifted => Shifted, CoinKind.Direct => [Math.Sqrt(0.1)], _ => Mean };
        var ideal = CoinProbability.Head(CoinProbability.HeadAmplitude(kind, amplitudes), iterations);
        var mixed = SupersamplingNoise.UniformHeadShare(kind, amplitudes.Length);
        Assert.Equal(ideal, SupersamplingNoise.CoinHeadProbability(kind, amplitudes, iterations, NoiseModel.None), 12);
        var previous = Math.Abs(ideal - mixed);
        foreach (var p in new[] { 1e-5, 1e-4, 1e-3, 3e-3, 1e-2, 3e-2 })
        {
            var distance = Math.Abs(SupersamplingNoise.CoinHeadProbability(kind, amplitudes, iterations, NoiseModel.Depolarizing(p)) - mixed);
            Assert.True(distance < previous, $"p = {p}: the head probability did not move towards {mixed}");
            previous = distance;
        }
        // At p = 0.9 every location is almost surely hit: a maximally mixed register.
        Assert.Equal(mixed, SupersamplingNoise.CoinHeadProbability(kind, amplitudes, iterations, NoiseModel.Depolarizing(0.9)), 6);
    }

    [Fact]
    public void MixedShareIsWhatAMaximallyMixedRegisterReadsAsAHead()
    {
        Assert.Equal(0.5, SupersamplingNoise.UniformHeadShare(CoinKind.Mean, 16));
        Assert.Equal(0.5, SupersamplingNoise.UniformHeadShare(CoinKind.Direct, 16));
        // The shifted coin's head is the coin at |1⟩ and 4 subpixel qubits at 0: one state of 32.
        Assert.Equal(1.0 / 32, SupersamplingNoise.UniformHeadShare(CoinKind.Shifted, 16));
        Assert.Equal(1.0 / 8, SupersamplingNoise.UniformHeadShare(CoinKind.Shifted, 3));
    }

    [Fact]
    public void FidelityIsOneFactorForThePreparationAndOnePerOperator()
    {
        // Φ = F₀ · F^m: the ratio of successive m is F per Grover operator.
        var noise = NoiseModel.Depolarizing(1e-3);
        foreach (var kind in new[] { CoinKind.Mean, CoinKind.Shifted, CoinKind.Direct })
        {
            var f = SupersamplingNoise.GroverOperatorFidelity(kind, Mean, noise);
            for (var m = 0; m < 4; m++)
                Assert.Equal(f, SupersamplingNoise.CoinFidelity(kind, Mean, m + 1, noise) / SupersamplingNoise.CoinFidelity(kind, Mean, m, noise), 12);
        }
        Assert.Equal(2 + 4 * 7, CoinNoiseLocations.Flip(CoinKind.Direct, [0.3], 7));
        // The direct coin's weight is one qubit's depolarizing channel per location, whatever the harmful share.
        Assert.Equal(Math.Pow(1 - 4e-3 / 3, 30), SupersamplingNoise.CoinFidelity(CoinKind.Direct, [0.3], 7, noise, new DepolarizingApproximation(0.2)), 12);
    }

    [Fact]
    public void QssReadoutMixesTowardsUniform()
    {
        var ideal = SupersamplingNoise.QssReadout(Mean, 3, NoiseModel.None);
        var noise = NoiseModel.Depolarizing(1e-3);
        var phi = SupersamplingNoise.QssFidelity(Mean, 3, noise);
        Assert.InRange(phi, 0.01, 0.99);
        var noisy = SupersamplingNoise.QssReadout(Mean, 3, noise);
        Assert.Equal(1, noisy.Sum(), 12);
        for (var y = 0; y < 8; y++) Assert.Equal(phi * ideal[y] + (1 - phi) / 8, noisy[y], 12);
        Assert.All(SupersamplingNoise.QssReadout(Mean, 3, NoiseModel.Depolarizing(0.9)), q => Assert.Equal(1.0 / 8, q, 6));
    }

    [Fact]
    public void NoisyAnalyticEngineSamplesTheModel()
    {
        // 20000 flips per coin, each head count inside its binomial acceptance interval; 20000 QSS readouts against
        // the model's distribution by chi-square (false-failure 1e-8 per check).
        var noise = NoiseModel.Depolarizing(3e-3);
        var engine = new AnalyticCoinEngine(new SeededRandom(5), noise);
        var coins = Coins.Take(4).Select(c => c with { Flips = 20000 }).ToArray();
        var heads = engine.FlipCoins(coins);
        for (var k = 0; k < coins.Length; k++)
        {
            var p = SupersamplingNoise.CoinHeadProbability(coins[k].Kind, coins[k].Amplitudes, coins[k].Iterations, noise);
            Assert.NotEqual(CoinProbability.Head(CoinProbability.HeadAmplitude(coins[k].Kind, coins[k].Amplitudes), coins[k].Iterations), p, 3);
            StatisticalBounds.AssertBinomial(heads[k], p, coins[k].Flips, $"analytic {coins[k].Kind} coin, m = {coins[k].Iterations}, under {noise}");
        }
        var readouts = engine.ReadCounters([new QssRequest(Mean, 3, 20000)])[0];
        StatisticalBounds.AssertFits(StatisticalBounds.Histogram(readouts, 8), SupersamplingNoise.QssReadout(Mean, 3, noise), "analytic QSS readout under noise");
    }
}
