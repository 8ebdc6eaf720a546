using System.Globalization;
using QuantumRayTracing.Experiments;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Tests.Engines;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Experiments;

/// <summary>`bench fullstate-performance`'s experiment on a pool it is given (as a cluster's): every call it counts went through that pool.</summary>
public sealed class FullStatePerformanceExperimentTests
{
    [Fact]
    public void RendersOnTheGivenPoolAndCountsItsCalls()
    {
        using var pool = new BridgePool(1);
        var settings = new FullStatePerformanceSettings([("qornell-8", Load("qornell-8.json"))], [1], BaselineLimit: long.MaxValue, Seed: 5, Workers: 3, pool);
        var report = FullStatePerformanceExperiment.Run(settings, _ => { });

        var renders = report.Table("renders");
        Assert.Equal(["baseline", "current"], renders.Rows.Select(r => renders.Cell(r, "engine")));
        // The render's calls, plus the 10 calls (a warm-up and 9 timed) that measure the call floor before each render.
        var calls = renders.Rows.Sum(r => long.Parse(renders.Cell(r, "calls"), NumberStyles.AllowThousands, CultureInfo.InvariantCulture));
        Assert.Equal(pool.Requests, calls + 2 * 10);
        // The primary ray at least (a 1x1 frame, whose primary and shadow passes make Grover runs), the same on both engines' pipelines.
        Assert.All(renders.Rows, r => Assert.True(int.Parse(renders.Cell(r, "rays"), NumberStyles.AllowThousands, CultureInfo.InvariantCulture) >= 1));
        Assert.All(renders.Rows, r => Assert.True(long.Parse(renders.Cell(r, "Grover runs"), NumberStyles.AllowThousands, CultureInfo.InvariantCulture) > 0));
        // The pool's workers, not the local worker count the settings would start without it.
        Assert.Contains("seed 5, 1 workers", report.Blocks.OfType<ReportText>().First().Markdown);
        Assert.Single(report.Table("ratios").Rows);
    }
}
