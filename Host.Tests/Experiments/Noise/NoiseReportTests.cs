using QuantumRayTracing.Experiments;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Tests.Experiments;

/// <summary>
/// <see cref="NoiseReport"/> on measurements made up here, so every figure it shows can be checked by hand: the model
/// check's table holds the measured share and the model's, and a run the model misses is named under it.
/// </summary>
public sealed class NoiseReportTests
{
    private static readonly NoiseBenchSettings ModelOnly = new(new HashSet<string> { "model" }, 1000, 16, [], 8, 0, [], 1);

    private static NoiseBenchResult Measured(params NoiseCheckRow[] rows) =>
        new("a test machine", TimeSpan.FromMinutes(1.5), rows, [], [], null, null, [], [], [], []);

    // N = 16, t = 1, r = 3 at p = 1e-3 over 152 noise locations: Φ = (1 − 1e-3)^(152 · 2/3) = 0.9037 and
    // sin²(7θ) = 0.9613 with sin²θ = 1/16, so the model's P(marked) = 0.9037 · 0.9613 + 0.0963 / 16 = 0.875.
    private static NoiseCheckRow Row(int hits) =>
        new("lookup", new GroverRequest(new MarkedSet(16, [3]), 3), NoiseModel.Depolarizing(1e-3), 152, 1000, hits);

    [Fact]
    public void TheModelTableHoldsTheMeasuredShareBesideTheModels()
    {
        var report = NoiseReport.Of(Measured(Row(870), Row(880)), ModelOnly);

        var table = report.Table("model-check");
        Assert.Equal(2, table.Rows.Count);
        // The lookup model is the circuit's evolution (checked against an independent density matrix by LookupCircuitDensityTests):
        // P(marked) = 0.8625 at p = 1e-3, and −ln Φ / p = 117 harm-weighted locations of the 152 (s = 2/3 would count 101).
        Assert.Equal(["lookup", "16", "1", "3", "1e-3", "152", "117", "0.870", "0.862"], table.Rows[0][..9]);
        Assert.Equal("+0.008", table.Cell(table.Rows[0], "gap"));
        Assert.Equal("0.880", table.Cell(table.Rows[1], "observed"));
        Assert.Equal("yes", table.Cell(table.Rows[1], "within δ + zσ"));
        Assert.Equal(NoiseReport.Title, report.Title);
        Assert.Contains(report.Blocks, b => b is ReportPlot { Name: "model-check" });
        Assert.Contains(report.Blocks.OfType<ReportText>(), t => t.Markdown.StartsWith("The model lies within δ + z·σ on all 2 rows.", StringComparison.Ordinal));
    }

    [Fact]
    public void ARunTheModelMissesIsNamedInTheParagraphUnderTheTable()
    {
        // 0.700 is 0.1625 below the model's 0.8625, σ = sqrt(0.8625 · 0.1375 / 1000) = 0.0109: about 15σ, past δ + zσ = 0.02 + 0.053.
        var report = NoiseReport.Of(Measured(Row(700)), ModelOnly);

        Assert.Equal("**no**", report.Table("model-check").Cell(report.Table("model-check").Rows[0], "within δ + zσ"));
        var summary = Assert.Single(report.Blocks.OfType<ReportText>(), t => t.Markdown.StartsWith("The model misses", StringComparison.Ordinal)).Markdown;
        Assert.Contains("The model misses on 1 of 1 rows: lookup N = 16, t = 1, r = 3, p = 1e-3: -0.162 (-14.9σ).", summary, StringComparison.Ordinal);
    }

    [Fact]
    public void ThePageOpensWithItsResultsInShortBeforeTheirDetail()
    {
        var report = NoiseReport.Of(Measured(Row(870), Row(700)), ModelOnly);

        var texts = report.Blocks.OfType<ReportText>().Select(t => t.Markdown).ToList();
        var summary = Assert.Single(texts, t => t.StartsWith("**In short**", StringComparison.Ordinal));
        Assert.Contains("- The searches' noise model lies within 0.02 + z·σ of the noisy simulator on 1 of 2 rows.", summary, StringComparison.Ordinal);
        Assert.True(texts.IndexOf(summary) < texts.FindIndex(t => t.StartsWith("**Noise model.**", StringComparison.Ordinal)));
        Assert.InRange(summary.Split('\n').Length, 2, 10);
    }
}
