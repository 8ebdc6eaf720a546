using QuantumRayTracing.Estimates;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Tests.Engines;

namespace QuantumRayTracing.Tests.Estimates;

/// <summary>
/// Estimates of the gate-level circuits: deterministic, the estimator's width equal to the registers
/// the scene needs, the extracted circuit agreeing with the estimator, and the compact construction
/// smaller than the baseline on the same ray.
/// </summary>
[Collection(QSharpCollection.Name)]
public sealed class ResourceEstimatorTests(FullStateFixture fixture)
{
    private ResourceEstimator Estimator(bool withCircuits = true) => new(fixture.Engine.Pool, QubitModel.Defaults, withCircuits);

    private static readonly Lazy<EstimateSubject> Small = new(() => EstimateSweep.Subject(8, 3));

    [Fact]
    public void SameInputGivesTheSameCountsTwice()
    {
        var subject = Small.Value;
        var jobs = new[] { (EstimatedCircuits.GroverIteration, subject), (EstimatedCircuits.GroverIteration, subject) };
        var estimates = Estimator().Estimate(jobs);
        var (first, second) = (estimates[0], estimates[1]);
        Assert.Equal(first.Logical, second.Logical);
        Assert.Equal(first.Physical, second.Physical);
        var (a, b) = (first.Counts!, second.Counts!);
        Assert.Equal(a.Qubits, b.Qubits);
        Assert.Equal((a.Native.Measurements, a.Native.Resets), (b.Native.Measurements, b.Native.Resets));
        // Only the measurement-conditioned phase corrections (Z, CZ) may differ between two simulated runs.
        foreach (var kind in a.Native.Gates.Keys.Union(b.Native.Gates.Keys).Except(CircuitCounts.OutcomeDependentKinds))
            Assert.True(a.Native.Gate(kind) == b.Native.Gate(kind), $"{kind}: {a.Native.Gate(kind)} then {b.Native.Gate(kind)}");
    }

    [Fact]
    public void ExtractedCircuitAgreesWithTheEstimatorAndTheModel()
    {
        var subject = Small.Value;
        foreach (var estimate in Estimator().Estimate(EstimatedCircuits.All.Select(c => (c, subject)).ToArray()))
        {
            var counts = estimate.Counts!;
            var what = $"{estimate.Circuit}: estimator {estimate.Logical}, circuit {string.Join(", ", counts.Native.Gates)}";
            // Independent sources: the estimator's counting run, the simulated trace, and OracleRegisters.
            Assert.True(estimate.Logical.Qubits == counts.Qubits, what);
            if (estimate.Registers is { } registers) Assert.True(registers.PeakQubits == estimate.Logical.Qubits, what);
            Assert.True(estimate.Logical.Ccz == counts.Native.Gate("CCX") + counts.Native.Gate("CCZ"), what);
            // Clifford + Toffoli circuits only: with arbitrary rotations (QSS's inverse QFT) the estimator counts
            // rotations by π/4 as T gates, which the trace keeps as Rz.
            if (EstimatedCircuits.Ray.Contains(estimate.Circuit))
                Assert.True(estimate.Logical.T == counts.Native.Gate("T") + counts.Native.Gate("T†"), what);
            Assert.True(estimate.Logical.Measurements == counts.Native.Measurements, what);
            // The CCX expansion adds 14 gates per CCX and keeps every other gate.
            Assert.True(counts.QiskitCcx.GateCount == counts.Native.GateCount + 14 * counts.Native.Gate("CCX"), what);
            Assert.True(counts.Native.Depth <= counts.Native.GateCount + counts.Native.Measurements + counts.Native.Resets, what);
            Assert.True(counts.QiskitCcx.Depth >= counts.Native.Depth, what);
            Assert.Equal(QubitModel.Defaults, estimate.Physical.Select(p => p.Model));
            Assert.All(estimate.Physical, p => Assert.True(p.PhysicalQubits > estimate.Logical.Qubits && p.RuntimeNanoseconds > 0, what));
        }
    }

    [Fact]
    public void SearchRunCostsItsIterationsTimesAnIteration()
    {
        // A run is the preparation, r iterations and a measurement: its Toffolis are r times an iteration's.
        var subject = Small.Value with { Iterations = 3 };
        var estimates = Estimator(withCircuits: false).Estimate([(EstimatedCircuits.GroverIteration, subject), (EstimatedCircuits.SearchRun, subject)]);
        Assert.Equal(3 * estimates[0].Logical.Ccz, estimates[1].Logical.Ccz);
    }

    [Fact]
    public void ExtrapolatedRunMatchesTheTracedRun()
    {
        // A run of r = 5 traced whole against the extrapolation from r = 1 and r = 2.
        var bridge = fixture.Engine.Pool.Bridges[0];
        CircuitCounts Trace(int r) => CircuitCounts.Parse(bridge.Circuit(EstimatedCircuits.SearchRun.Expression(Small.Value with { Iterations = r })));
        var traced = Trace(5);
        var extrapolated = CircuitCounts.Extrapolate(Trace(1), Trace(2), 5);
        Assert.True(extrapolated.Extrapolated);
        Assert.Equal(traced.Qubits, extrapolated.Qubits);
        Assert.Equal((traced.Native.Measurements, traced.Native.Resets), (extrapolated.Native.Measurements, extrapolated.Native.Resets));
        foreach (var kind in traced.Native.Gates.Keys.Except(CircuitCounts.OutcomeDependentKinds))
            Assert.True(traced.Native.Gate(kind) == extrapolated.Native.Gate(kind), $"{kind}: traced {traced.Native.Gate(kind)}, extrapolated {extrapolated.Native.Gate(kind)}");
        // The depth moves only with the random corrections (a few percent).
        Assert.InRange(extrapolated.Native.Depth, 0.95 * traced.Native.Depth, 1.05 * traced.Native.Depth);
        Assert.InRange(extrapolated.QiskitCcx.Depth, 0.95 * traced.QiskitCcx.Depth, 1.05 * traced.QiskitCcx.Depth);
    }

    [Fact]
    public void WidthIsTheSceneRegistersAndGrowsWithLog2N()
    {
        int[] sizes = [4, 16, 64, 256];
        var constructions = new[] { OracleConstruction.Narrow, OracleConstruction.Compact };
        var subjects = sizes.Select(n => EstimateSweep.Subject(n, 4)).ToArray();
        var jobs = constructions.SelectMany(k => subjects.Select(s => (EstimatedCircuits.Oracle, s.With(k)))).ToArray();
        var estimates = Estimator(withCircuits: false).Estimate(jobs);
        foreach (var estimate in estimates)
        {
            var input = estimate.Subject.Oracle;
            var registers = OracleRegisters.ForOracle(input);
            var what = $"N = {input.Table.Count}, {input.Construction}: {registers}, estimator {estimate.Logical.Qubits}";
            Assert.True(registers.PeakQubits == estimate.Logical.Qubits, what);
            // The registers the scene needs: index ceil(log2 N), rpc and bounds of the grid's bits, depth, flags, output.
            Assert.Equal(SceneIndexBits(input.Table.Count), registers.IndexQubits);
            Assert.Equal((1 + input.Construction.BoundRegisters) * 4, registers.CoordinateRegisterQubits);
        }
        Assert.All(subjects, s => Assert.Equal(subjects[0].Oracle.Table.DepthBits, s.Oracle.Table.DepthBits));
        var narrow = estimates.Take(sizes.Length).Select(e => e.Logical.Qubits).ToArray();
        var registersOnly = estimates.Take(sizes.Length).Select(e => e.Registers!.Value.RegisterQubits).ToArray();
        for (var k = 1; k < sizes.Length; k++)
        {
            // Each factor 4 in N adds two index qubits to the registers, and at most two lookup helpers.
            Assert.Equal(2, registersOnly[k] - registersOnly[k - 1]);
            Assert.InRange(narrow[k] - narrow[k - 1], 2, 4);
        }
        // 64 times the primitives, a dozen more qubits at most: nothing grows with N itself.
        Assert.True(narrow[^1] - narrow[0] <= 12, string.Join(", ", narrow));
    }

    [Fact]
    public void CompactOracleIsSmallerThanTheBaselineOnTheSameRay()
    {
        var subject = EstimateSweep.Subject(16, 4);
        var estimates = Estimator().Estimate([
            (EstimatedCircuits.Oracle, subject.With(OracleConstruction.Baseline)),
            (EstimatedCircuits.Oracle, subject.With(OracleConstruction.Compact)),
            (EstimatedCircuits.Oracle, subject.With(OracleConstruction.Narrow)),
        ]);
        var (baseline, compact, narrow) = (estimates[0], estimates[1], estimates[2]);
        Assert.True(compact.Logical.Ccz < baseline.Logical.Ccz, $"CCZ {baseline.Logical.Ccz} → {compact.Logical.Ccz}");
        Assert.True(compact.Logical.Measurements < baseline.Logical.Measurements);
        Assert.True(compact.Counts!.Native.GateCount < baseline.Counts!.Native.GateCount);
        Assert.True(compact.Counts.QiskitCcx.GateCount < baseline.Counts.QiskitCcx.GateCount);
        // Unloading by lookup instead of measurement costs Toffolis and no width here.
        Assert.True(narrow.Logical.Ccz > compact.Logical.Ccz);
        Assert.True(narrow.Logical.Qubits <= compact.Logical.Qubits);
    }

    private static int SceneIndexBits(int count) => (int)Math.Ceiling(Math.Log2(count));
}
