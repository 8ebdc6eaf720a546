using QuantumRayTracing.Noise;
using QuantumRayTracing.Experiments;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;
using static QuantumRayTracing.Experiments.NoiseEstimationExperiment;

namespace QuantumRayTracing.Tests.Experiments;

public class NoiseEstimationTests
{
    [Theory]
    [InlineData(0.01)]
    [InlineData(0.03)]
    [InlineData(0.1)]
    public void TheRateForADecayGivesTheDirectCoinThatDecay(double decay)
    {
        var rate = RateForDecay(decay);
        Assert.InRange(rate, 1e-4, 0.1);
        Assert.Equal(decay, DecayOf(CoinKind.Direct, [0.5], rate), 9);
    }

    [Fact]
    public void FallbackRateIsWhereTheErrorStaysAtOrAboveMonteCarlo()
    {
        // QCoin below MC at 0 and 1e-4, above from 1e-2 on: the gap goes from −0.01 at 1e-4 to +0.01 at 1e-2, so it crosses at 1e-3 (log scale).
        MethodPoint[] points =
        [
            new(0, 100, "MC", 0.03), new(0, 100, "QCoin", 0.01),
            new(1e-4, 100, "MC", 0.03), new(1e-4, 100, "QCoin", 0.02),
            new(1e-2, 100, "MC", 0.03), new(1e-2, 100, "QCoin", 0.04),
            new(1e-1, 100, "MC", 0.03), new(1e-1, 100, "QCoin", 0.05),
            new(0, 100, "QSS", 0.05), new(1e-4, 100, "QSS", 0.01), new(1e-2, 100, "QSS", 0.01), new(1e-1, 100, "QSS", 0.02),
        ];
        Assert.Equal(1e-3, NoiseEstimationReport.FallbackRate(points, "QCoin", 100)!.Value, 9);
        Assert.Null(NoiseEstimationReport.FallbackRate(points, "QSS", 100));
    }

    [Fact]
    public void ASmallRunReportsEveryPart()
    {
        var settings = new NoiseEstimationSettings(10, NoiseEstimationSettings.DefaultDeviceRate, 2, 1);
        var result = NoiseEstimationExperiment.Run(settings, _ => { });
        var report = NoiseEstimationReport.Build(result, settings, "test machine");
        var headings = report.Blocks.OfType<QuantumRayTracing.Reports.ReportHeading>().Select(h => h.Text).ToArray();
        Assert.Equal(7, headings.Length);
        Assert.Equal(["Fig. 10", "Fig. 11", "Fig. 12"], headings.Take(3).Select(h => h[..7]));
        Assert.Equal(DeviceFigures.FitOneQubitRates.Length * 8, result.Device.Fit.Scan.Count);
        Assert.Equal(2 + DeviceFigures.FigureElevenTwoQubitRates.Length + 2, result.Device.FigureEleven.Count);
        // Fig. 10: every rate, coin and k that fits the budget; each k = 0 point is Monte Carlo.
        Assert.Equal(2 * NoiseEstimationSettings.StepRates.Length, result.Steps.Select(p => (p.Coin, p.Rate)).Distinct().Count());
        Assert.All(result.Steps, p => Assert.InRange(p.Error, 0, 1));
        Assert.Equal(5, result.Images.Count);
        Assert.Equal(NoiseEstimationSettings.AwareDecays.Length, result.Aware.Count);
    }

    [Fact]
    public void ExactQssErrorMatchesSampledQss()
    {
        // 20,000 uniform random means through QSS (t = 3) on the analytic engine: the sampled mean absolute error lies within
        // z = 4.89 standard errors of the exact one (false-failure 1e-6).
        var random = new QuantumRayTracing.Randomness.SeededRandom(8);
        var means = Enumerable.Range(0, 20_000).Select(_ => new[] { random.NextDouble() }).ToArray();
        using var engine = new DirectCoinEngine(new AnalyticCoinEngine(new QuantumRayTracing.Randomness.SeededRandom(9)));
        var estimates = new QssEstimator(3).Estimate(means, engine);
        var errors = means.Select((v, j) => Math.Abs(estimates[j] - v[0])).ToArray();
        var mean = errors.Average();
        var sigma = Math.Sqrt(errors.Sum(e => (e - mean) * (e - mean)) / (errors.Length - 1) / errors.Length);
        Assert.InRange(mean, DeviceFigures.ExactQssError(3) - 4.89 * sigma, DeviceFigures.ExactQssError(3) + 4.89 * sigma);
    }

    [Fact]
    public void TheUnamplifiedCoinsPlateauIsTheReadoutsBias()
    {
        // MC at f = ½ with 10,000 flips, 2000 runs: under one-qubit noise alone its error stays MC's (about 0.004), with the readout
        // P0 = 0.02, P1 = 0.1 it sits at the bias |P0 − P1|/2 = 0.04; the two differ by far more than sampling (σ below 1e-4).
        var trials = Enumerable.Repeat(new[] { 0.5 }, 2000).ToArray();
        double Error(DeviceNoiseModel device)
        {
            using var engine = new DirectCoinEngine(new AnalyticCoinEngine(new QuantumRayTracing.Randomness.SeededRandom(3), device: device));
            return new MonteCarloEstimator(10_000).Estimate(trials, engine).Average(e => Math.Abs(e - 0.5));
        }
        Assert.InRange(Error(new DeviceNoiseModel(1e-2, 0)), 0.0035, 0.0045);
        Assert.InRange(Error(new DeviceNoiseModel(1e-2, 0, 0.02, 0.1)), 0.039, 0.041);
    }
}
