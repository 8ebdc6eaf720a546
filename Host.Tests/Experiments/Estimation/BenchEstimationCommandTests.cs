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
