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
    }
}
