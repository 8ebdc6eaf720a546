using QuantumRayTracing.Estimates;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Output;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Tests.Estimates;

/// <summary>
/// The frame's sums on a hand-made recording with made-up prices, small enough to add up by hand:
/// passes kept apart, r = 0 draws unpriced, batches scheduled one after another on K processors.
/// </summary>
public sealed class FrameCostSumTests
{
    private static readonly QubitModel Model = QubitModel.Defaults[0];
    private static readonly OracleShape Narrow = new(8, 3, 4, 2, 1, 3);
    private static readonly OracleShape Wide = new(8, 3, 4, 5, 2, 6);

    private static PhysicalEstimate Physical(long qubits, double nanoseconds, int distance, double failure) =>
        new(Model, qubits, nanoseconds, distance, 1) { Errors = new RunErrors(failure, 1, 1, 0, 0, 0) };

    private static RunPrice Price(int qubits, long ccz, long measurements, PhysicalEstimate split, PhysicalEstimate alone) =>
        new(new LogicalCounts(qubits, 0, 0, 0, ccz, 0, measurements), [split], [alone]);

    [Fact]
    public void PassesAndTotalAddUpByHand()
    {
        // primary: batch 0 = {narrow r1, narrow r1, wide r2}, batch 1 = {narrow r0, wide r2}; shadow: batch 2 = {narrow r1}.
        RecordedRun[] runs =
        [
            new("primary", 0, Narrow, 1), new("primary", 0, Narrow, 1), new("primary", 0, Wide, 2),
            new("primary", 1, Narrow, 0), new("primary", 1, Wide, 2),
            new("shadow", 2, Narrow, 1),
        ];
        var prices = new Dictionary<(OracleShape, int), RunPrice>
        {
            [(Narrow, 1)] = Price(20, 10, 4, Physical(1000, 3, 9, 1e-4), Physical(500, 2, 5, 1e-3)),
            [(Wide, 2)] = Price(30, 25, 7, Physical(2000, 5, 11, 2e-4), Physical(900, 4, 7, 2e-3)),
        };
        var passes = new[] { "primary", "shadow" }.Select(n => new PassMetrics(n, 1, 1, default(SearchCost), 0, TimeSpan.Zero)).ToArray();
        var recording = new FrameRecording(new RenderResult(new RgbImage(1, 1), passes), runs, new Dictionary<OracleShape, OracleInput>());
        var cost = FrameCost.Of(recording, prices, [Model], new FrameBudget(0.01, 5), qpus: 2);

        var primary = cost.Passes.Single(p => p.Name == "primary");
        Assert.Equal((4L, 1L), (primary.QuantumRuns, primary.ClassicalDraws));
        Assert.Equal(10 + 10 + 25 + 25, primary.Logical.Ccz);
        Assert.Equal(4 + 4 + 7 + 7, primary.Logical.Measurements);
        Assert.Equal(30, primary.Logical.Qubits);
        Assert.Equal(new SearchCost(2 + 2 + 3 + 3, 1 + 1 + 2 + 2, 0, 5), primary.Queries);
        var p = primary.Split[0];
        Assert.Equal(2000, p.PhysicalQubits);
        Assert.Equal(3 + 3 + 5 + 5, p.SequentialNanoseconds);
        // Batch 0 on 2 processors: 5 | 3 + 3 → 6; batch 1: 5 (the draw is free) → 11.
        Assert.Equal(6 + 5, p.ParallelNanoseconds);
        Assert.Equal((9, 11), (p.MinCodeDistance, p.MaxCodeDistance));
        Assert.Equal(1e-4 + 1e-4 + 2e-4 + 2e-4, p.FailureBound, 1e-15);
        Assert.Equal(2 + 2 + 4 + 4, primary.Alone[0].SequentialNanoseconds);

        var total = cost.Total;
        Assert.Equal((5L, 1L), (total.QuantumRuns, total.ClassicalDraws));
        Assert.Equal(primary.Logical.Ccz + 10, total.Logical.Ccz);
        Assert.Equal(16 + 3, total.Split[0].SequentialNanoseconds);
        Assert.Equal(11 + 3, total.Split[0].ParallelNanoseconds);
        Assert.Equal(6e-4 + 1e-4, total.Split[0].FailureBound, 1e-15);
    }
}
