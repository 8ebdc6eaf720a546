using QuantumRayTracing.Estimates;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Tests.Estimates;

/// <summary>
/// The sweep's plots from estimates made up here (no bridge): which plots a sweep draws and that each
/// holds its data.
/// </summary>
public sealed class SweepPlotsTests
{
    private static readonly int[] Primitives = [4, 16, 64];
    private static readonly int[] Bits = [2, 4];

    private static SweepReport Report(bool withCircuits)
    {
        var subject = EstimateSweep.Subject(4, 2);
        var points = new Dictionary<(int, int, string), CircuitEstimate>();
        foreach (var (n, c, k) in SweepReport.Wanted(Primitives, Bits, []))
        {
            var logical = new LogicalCounts(20 + n / 4, 0, 0, 0, 10 * n, 0, 12 * n);
            var tally = new GateTally(new Dictionary<string, long> { ["CCX"] = 10 * n }, 100 * n, 12 * n, 12 * n, 50 * n);
            var counts = withCircuits ? new CircuitCounts(logical.Qubits, 124 * n, tally, tally with { GateCount = 240 * n }) : null;
            points[(n, c, k.Name)] = new CircuitEstimate(EstimatedCircuits.Oracle, subject.With(k), logical, [], counts, null);
        }
        return new SweepReport(points, []);
    }

    [Fact]
    public void EveryPlotIsDrawnWithCircuitCounts()
    {
        var plots = SweepPlots.Draw(Report(withCircuits: true), Primitives, Bits);
        Assert.Equal(["ccz-vs-primitives", "qubits-vs-primitives", "gates-vs-primitives", "qubits-vs-bits", "gates-vs-bits"], plots.Select(p => p.Suffix));
        var images = plots.Select(p => PlotImage.Render(p.Spec)).ToArray();
        Assert.All(images, image => Assert.Equal((800, 500), (image.Width, image.Height)));
        // Each plot draws its series in colour on a white background.
        Assert.All(plots.Zip(images), p => Assert.True(HasColour(p.Second.Pixels.ToArray()), $"{p.First.Suffix} has no coloured pixel"));
    }

    private static bool HasColour(byte[] rgb)
    {
        for (var k = 0; k + 2 < rgb.Length; k += 3)
            if (rgb[k] != rgb[k + 1] || rgb[k + 1] != rgb[k + 2]) return true;
        return false;
    }

    [Fact]
    public void GatePlotsNeedTheExtractedCircuits()
    {
        var plots = SweepPlots.Draw(Report(withCircuits: false), Primitives, Bits);
        Assert.Equal(["ccz-vs-primitives", "qubits-vs-primitives", "qubits-vs-bits"], plots.Select(p => p.Suffix));
    }
}
