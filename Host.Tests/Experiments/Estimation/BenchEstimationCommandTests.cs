using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;
using QuantumRayTracing.Randomness;
using System.Globalization;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Experiments;
using QuantumRayTracing.Tests.Cli;

namespace QuantumRayTracing.Tests.Experiments;

/// <summary>
/// `bench estimation` on a tiny harness: the report, its plots and its CSV are written, every estimator has a point at every
/// budget it can run, no estimator spent more queries than its budget (the engine's own count, averaged), and a file it did
/// not write stops it before the work.
/// </summary>
public sealed class BenchEstimationCommandTests : IDisposable
{
    private readonly ScratchDirectory _scratch = new("qrt-bench-estimation");

    public void Dispose() => _scratch.Dispose();

    [Fact]
    public void WritesEveryEstimatorAtEveryBudgetWithinItsBudget()
    {
        var (code, error) = ConsoleCapture.Run("bench", "estimation", "--trials", "10", "--image-size", "1", "--no-noise", "-o", _scratch.File("estimation.md"));
        Assert.True(code == ExitCodes.Success, error);
        Assert.Equal(["estimation-means.png", "estimation-pixels.png", "estimation.csv", "estimation.md"], _scratch.FileNames().Order());
        // Fields split at the commas outside quotes ("IQAE, original" is one).
        var rows = File.ReadAllLines(_scratch.File("estimation.csv")).SkipWhile(l => !l.StartsWith("input,")).Skip(1)
            .Select(l => System.Text.RegularExpressions.Regex.Split(l, ",(?=(?:[^\"]*\"[^\"]*\")*[^\"]*$)")).ToArray();
        foreach (var input in new[] { "means", "pixels" })
            foreach (var (label, create) in EstimationExperiment.Estimators)
                foreach (var budget in EstimationSettings.Budgets.Where(b => create(b) is not null))
                {
                    var row = Assert.Single(rows, r => r[0] == input && r[2].Trim('"') == label && r[3] == budget.ToString(CultureInfo.InvariantCulture));
                    var spent = double.Parse(row[4], CultureInfo.InvariantCulture);
                    Assert.True(spent <= budget && spent >= 0.5 * budget, $"{label} at {budget}: {spent} queries spent on average");
                }
        Assert.Contains("Fitted log-log slopes", File.ReadAllText(_scratch.File("estimation.md")));
    }

    /// <summary>
    /// With noise, the report has the device-rate table, and its points ran on the device model: the unamplified coin read
    /// through the fitted readout error is off by about ∫|P0 − (P0 + P1)f| df ≈ 0.043 on uniform means, where classical
    /// Monte Carlo at 3,200 flips errs about 0.006 (200 means: the mean error's standard error is about 0.002).
    /// </summary>
    [Fact]
    public void MeasuresEveryEstimatorAtTheDevicesRates()
    {
        var (code, error) = ConsoleCapture.Run("bench", "estimation", "--trials", "10", "--image-size", "1", "-o", _scratch.File("estimation.md"));
        Assert.True(code == ExitCodes.Success, error);
        Assert.Contains("## At the device's rates", File.ReadAllText(_scratch.File("estimation.md")));
        var deviceRows = File.ReadAllLines(_scratch.File("estimation.csv")).Count(l => l.EndsWith(",fig10-fit", StringComparison.Ordinal));
        Assert.Equal(EstimationSettings.NoisyBudgets.Sum(b => EstimationExperiment.Estimators.Count(e => e.Create(b) is not null)), deviceRows);

        var random = new SeededRandom(3);
        var means = Enumerable.Range(0, 200).Select(_ => new[] { random.NextDouble() }).ToArray();
        using var device = new DirectCoinEngine(new AnalyticCoinEngine(random.Fork(1), device: EstimationSettings.DeviceRates));
        var biased = new MonteCarloEstimator(3200).Estimate(means, device).Select((e, j) => Math.Abs(e - means[j][0])).Average();
        Assert.InRange(biased, 0.035, 0.052);
    }

    [Fact]
    public void AFileItDidNotWriteBesideTheReportStopsItBeforeTheWork()
    {
        File.WriteAllText(_scratch.File("estimation-noise.png"), "someone's file\n");
        var (code, error) = ConsoleCapture.Run("bench", "estimation", "--trials", "10", "-o", _scratch.File("estimation.md"));
        Assert.Equal(ExitCodes.BadInput, code);
        Assert.DoesNotContain("rendering the Qornell box", error);
        Assert.Equal(["estimation-noise.png"], _scratch.FileNames());
    }
}
