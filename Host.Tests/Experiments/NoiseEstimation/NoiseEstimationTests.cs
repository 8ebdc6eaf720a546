using QuantumRayTracing.Experiments;
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
        Assert.Equal(4, headings.Length);
        // Fig. 10: every rate, coin and k that fits the budget; each k = 0 point is Monte Carlo.
        Assert.Equal(2 * NoiseEstimationSettings.StepRates.Length, result.Steps.Select(p => (p.Coin, p.Rate)).Distinct().Count());
        Assert.All(result.Steps, p => Assert.InRange(p.Error, 0, 1));
        Assert.Equal(5, result.Images.Count);
        Assert.Equal(NoiseEstimationSettings.AwareDecays.Length, result.Aware.Count);
    }
}
