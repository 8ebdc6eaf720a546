using System.Globalization;
using QuantumRayTracing.Experiments;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Scenes.Generation;

namespace QuantumRayTracing.Tests.Experiments;

/// <summary>`bench accuracy` on 4x4 images and one seed: its tables hold the cells it measured, summed as they say.</summary>
public sealed class AccuracyExperimentTests
{
    // The growth tables, which these tests do not read, at their smallest: one N (the smallest the command uses) and
    // two seeds, so the seed spread still renders a seed beyond the growth table's first.
    private static readonly Lazy<Report> Report = new(() =>
        AccuracyExperiment.Run(new AccuracySettings([4], 1, 4, DefaultScene.Load(null)) { Growth = [64], GrowthSeeds = 2 }, _ => { }));

    [Fact]
    public void EachKindsRowHoldsItsMeasuredCells()
    {
        var table = Report.Value.Table("sizes");
        Assert.Equal(RandomScene.Kinds.Length, table.Rows.Count);
        var row = Assert.Single(table.Rows, r => r[0].StartsWith("ties", StringComparison.Ordinal));
        var cells = AccuracyBenchmark.Measure(RandomSceneKind.Ties, 4, [1], AccuracyBenchmark.Standard);
        for (var c = 0; c < cells.Count; c++)
        {
            Assert.Equal($"{cells[c].WrongPixels} of 16", table.Cell(row, $"{cells[c].Configuration}: wrong pixels"));
            Assert.Equal(cells[c].IntPerRay.ToString("0.0", CultureInfo.InvariantCulture), table.Cell(row, "Int/Ray", c));
        }
        Assert.Equal(cells[0].AllowedWrong.ToString("0.0", CultureInfo.InvariantCulture), table.Cell(row, "default: expected wrong"));
    }

    [Fact]
    public void TheAlternativesSumEveryKindButTheDeepScenes()
    {
        var table = Report.Value.Table("alternatives");
        Assert.Equal(AccuracyBenchmark.Alternatives.Select(c => c.Name), table.Rows.Select(r => r[0]));
        var cells = RandomScene.Kinds.Where(k => k != RandomSceneKind.Deep)
            .SelectMany(k => AccuracyBenchmark.Measure(k, 4, [1], AccuracyBenchmark.Alternatives)).Where(c => c.Configuration == "2 required misses").ToArray();
        var (wrong, pixels) = (cells.Sum(c => c.WrongPixels), cells.Sum(c => c.Pixels));
        Assert.Equal(16 * cells.Length, pixels);
        Assert.StartsWith($"{wrong} of {pixels} (", table.Cell(table.Rows.Single(r => r[0] == "2 required misses"), "4x4: wrong"));
    }
}
