using QuantumRayTracing.Randomness;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;
using QuantumRayTracing.Tests.Engines;
using QuantumRayTracing.Tests.Statistics;

namespace QuantumRayTracing.Tests.Estimation;

/// <summary>
/// The Q# circuits against their closed forms and the analytic engine. The simulator cannot be seeded, so every
/// check is statistical with false-failure probability <see cref="StatisticalBounds.FalseFailure"/> (at most 20 per test).
/// </summary>
[Collection(QSharpCollection.Name)]
public class FullStateCoinEngineTests(FullStateFixture fixture)
{
    private FullStateCoinEngine Engine => new(fixture.Engine.Pool, ownsPool: false);

    public static readonly CoinRequest[] CoinCases =
    [
        // N = 5 is not a power of two: the exact uniform preparation matters.
        new(CoinKind.Mean, CoinValues.MeanCoin([0.1, 0.9, 0.4, 0.0, 1.0]), 0, 800),
        new(CoinKind.Mean, CoinValues.MeanCoin([0.1, 0.2, 0.0, 0.05]), 2, 800),
        new(CoinKind.Mean, CoinValues.MeanCoin([1.0, 1.0]), 3, 200),
        new(CoinKind.Mean, CoinValues.MeanCoin([0.0, 0.0, 0.0]), 2, 200),
        // Shifted amplitudes of both signs: F − E with E inside the range of F.
        new(CoinKind.Shifted, CoinValues.Shifted([0.3, 0.5, 0.2, 0.6], 0.3), 1, 800),
        new(CoinKind.Shifted, CoinValues.Shifted([0.7, 0.9, 0.6], 0.65), 2, 800),
        new(CoinKind.Shifted, [0.25], 3, 800),
        // The direct coin's one qubit, between the others: the engine's separate batch keeps the request order.
        new(CoinKind.Direct, CoinValues.MeanCoin([0.1, 0.9, 0.4, 0.0, 1.0]), 2, 800),
        new(CoinKind.Mean, CoinValues.MeanCoin([0.3, 0.6]), 1, 800),
        new(CoinKind.Direct, [-0.3], 5, 800),
    ];

    [Fact]
    public void CoinHeadsMatchClosedFormAndAnalyticEngine()
    {
        var fullstate = Engine.FlipCoins(CoinCases);
        for (var k = 0; k < CoinCases.Length; k++)
            StatisticalBounds.AssertBinomial(fullstate[k], ExactHead(CoinCases[k]), CoinCases[k].Flips, $"{CoinCases[k].Kind} coin case {k}, m = {CoinCases[k].Iterations}");
        var analytic = new AnalyticCoinEngine(new SeededRandom(5)).FlipCoins(CoinCases);
        for (var k = 0; k < CoinCases.Length; k++)
        {
            var n = CoinCases[k].Flips;
            StatisticalBounds.AssertBinomial(analytic[k], ExactHead(CoinCases[k]), n, $"analytic {CoinCases[k].Kind} coin case {k}");
            // A certain coin (by its closed form) leaves one cell, which no chi-square can test: both engines must then agree exactly.
            var p = ExactHead(CoinCases[k]);
            if (p < 1e-12 || p > 1 - 1e-12)
            {
                Assert.Equal(fullstate[k], analytic[k]);
                continue;
            }
            // A nearly certain coin can land on one cell by chance (p = 0.995: 800 heads of 800 has probability 1.8 %); both
            // engines were held to the closed form above, and no chi-square applies to one cell.
            if (fullstate[k] % n == 0 || analytic[k] % n == 0) continue;
            StatisticalBounds.AssertSameDistribution([fullstate[k], n - fullstate[k]], [analytic[k], n - analytic[k]], $"coin case {k}");
        }
    }

    /// <summary>
    /// The ancilla-controlled Grover power on the simulator against cos²(kθ), the closed form the analytic engine draws
    /// from. With the wrong fringe in the expectation (cos²(2kθ)) the k = 1 case fails: 414 zeros of 800 against an
    /// acceptance interval of [0, 12].
    /// </summary>
    [Fact]
    public void AncillaZerosMatchTheClosedForm()
    {
        AncillaPhaseRequest[] cases =
        [
            new(CoinValues.MeanCoin([0.1, 0.9, 0.4, 0.0, 1.0]), 0, 200),
            new(CoinValues.MeanCoin([0.1, 0.9, 0.4, 0.0, 1.0]), 1, 800),
            new(CoinValues.MeanCoin([0.1, 0.2, 0.0, 0.05]), 3, 800),
            new(CoinValues.MeanCoin([0.3, 0.6]), 2, 800),
            new(CoinValues.MeanCoin([0.8]), 5, 800),
            new(CoinValues.MeanCoin([1.0, 1.0]), 3, 200),
        ];
        var zeros = Engine.CountAncillaZeros(cases);
        for (var k = 0; k < cases.Length; k++)
            StatisticalBounds.AssertBinomial(zeros[k], CoinProbability.AncillaZero(CoinProbability.HeadAmplitude(CoinKind.Mean, cases[k].Amplitudes), cases[k].Power),
                cases[k].Shots, $"ancilla case {k}, k = {cases[k].Power}");
    }

    [Fact]
    public void QssReadoutsFitClosedFormAndAnalyticEngine()
    {
        // Mean 2/3 over three subpixels (not a power of two), three counter bits: the readout spreads over several values.
        var request = new QssRequest(CoinValues.MeanCoin([1.0, 0.0, 1.0]), 3, 1500);
        var fullstate = StatisticalBounds.Histogram(Engine.ReadCounters([request])[0], 8);
        var analytic = StatisticalBounds.Histogram(new AnalyticCoinEngine(new SeededRandom(8)).ReadCounters([request])[0], 8);
        StatisticalBounds.AssertFits(fullstate, ExactReadout(2.0 / 3, 3), "fullstate QSS readout vs exact");
        StatisticalBounds.AssertSameDistribution(fullstate, analytic, "fullstate vs analytic QSS readout");
    }

    [Fact]
    public void MeasuredLookupTableColumnsFitExactTable()
    {
        const int shots = 400;
        var measured = QssLookupTable.Measure(4, 3, Engine, shots);
        for (var h = 0; h <= 4; h++)
        {
            var counts = Enumerable.Range(0, 8).Select(y => (int)Math.Round(measured.Probabilities[y, h] * shots)).ToArray();
            Assert.Equal(shots, counts.Sum());
            var exact = ExactReadout(h / 4.0, 3);
            if (exact.Count(p => p > 0) == 1)
            {
                // h = 0 reads 0 with certainty: nothing to fit, everything must be there.
                Assert.Equal(shots, counts[Array.FindIndex(exact, p => p > 0)]);
                continue;
            }
            StatisticalBounds.AssertFits(counts, exact, $"measured table column h = {h}");
        }
    }

    /// <summary>The head probability derived here from the amplitudes, independently of <see cref="CoinProbability"/>.</summary>
    private static double ExactHead(CoinRequest c)
    {
        var a = c.Amplitudes;
        var s = c.Kind != CoinKind.Shifted ? Math.Sqrt(a.Sum(x => x * x) / a.Length) : Math.Abs(a.Average());
        var angle = (2 * c.Iterations + 1) * Math.Asin(Math.Min(1, s));
        return Math.Min(1, Math.Pow(Math.Sin(angle), 2));
    }

    /// <summary>
    /// Amplitude estimation's readout distribution summed directly over the counter's branches:
    /// amplitude of y = (1/P) Σ_j e^{2πi j(ω − y/P)} for ω = ±θ/π, each branch with weight ½.
    /// </summary>
    internal static double[] ExactReadout(double mean, int counterBits)
    {
        var size = 1 << counterBits;
        var theta = Math.Asin(Math.Sqrt(mean));
        var result = new double[size];
        for (var y = 0; y < size; y++)
            foreach (var omega in new[] { theta / Math.PI, -theta / Math.PI })
            {
                var (re, im) = (0.0, 0.0);
                for (var j = 0; j < size; j++)
                {
                    var phase = 2 * Math.PI * j * (omega - (double)y / size);
                    re += Math.Cos(phase) / size;
                    im += Math.Sin(phase) / size;
                }
                result[y] += 0.5 * (re * re + im * im);
            }
        return result.Select(p => p < 1e-15 ? 0 : p).ToArray();
    }
}
