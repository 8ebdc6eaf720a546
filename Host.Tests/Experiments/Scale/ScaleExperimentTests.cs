using QuantumRayTracing.Engines;
using QuantumRayTracing.Experiments;

namespace QuantumRayTracing.Tests.Experiments;

/// <summary>`bench scale` on two tiny sizes: each render runs in a child process whose peak memory and times it reads.</summary>
public class ScaleExperimentTests
{
    [LinuxFact("reads the child's peak memory from /proc")]
    public void MeasuresEachRenderInAProcessOfItsOwn()
    {
        var settings = new ScaleSettings(Path.Combine(RepositoryPaths.Scenes, "qornell-64.json"), [8, 16], [EngineKind.Classical, EngineKind.Bvh], 1);
        var report = ScaleExperiment.Run(settings, _ => { });
        var table = Assert.Single(report.Blocks.OfType<QuantumRayTracing.Reports.ReportTextTable>()).Table;
        Assert.Equal(4, table.Rows.Count);
        foreach (var row in table.Rows)
        {
            Assert.EndsWith(" s", row[3]);
            // A .NET process with the renderer loaded takes tens of megabytes; a render of 256 pixels adds little.
            Assert.Matches(@"^\d+ MB$", row[5]);
            Assert.InRange(int.Parse(row[5].Split(' ')[0], System.Globalization.CultureInfo.InvariantCulture), 20, 1000);
        }
        // Brute force tests every one of the 64 primitives; the BVH culls most of them.
        var intPerRay = table.Header.ToList().IndexOf("Int/Ray");
        var perRay = table.Rows.Select(r => double.Parse(r[intPerRay], System.Globalization.CultureInfo.InvariantCulture)).ToArray();
        Assert.True(perRay[0] > 40 && perRay[1] < perRay[0] / 2, string.Join(", ", perRay));
        // Both engines search only classically: each row has its tests per second.
        var rate = table.Header.ToList().IndexOf("tests/s");
        Assert.All(table.Rows, r => Assert.Matches(@"^\d+ M$", r[rate]));
    }

    /// <summary>Tests per second are #C_Int over the render's wall time, and only where every search is classical.</summary>
    [Fact]
    public void TestsPerSecondAreTheClassicalTestsOverTheRenderTime()
    {
        ScaleExperiment.Row Row(EngineKind engine, double? seconds) => new(engine, 2048, seconds, 1, 0, 61, null, null, null) { ClassicalTests = 850_000_000 };
        Assert.Equal(170e6, Row(EngineKind.Classical, 5).TestsPerSecond!.Value, 1e-3);
        Assert.Equal(85e6, Row(EngineKind.Bvh, 10).TestsPerSecond!.Value, 1e-3);
        // The analytic engine's #C_Int are only its verifications, not its work; a refused render has no time.
        Assert.Null(Row(EngineKind.Analytic, 5).TestsPerSecond);
        Assert.Null(Row(EngineKind.Classical, null).TestsPerSecond);
    }
}
