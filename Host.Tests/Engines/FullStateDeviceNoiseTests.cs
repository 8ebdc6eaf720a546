using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Search;
using Xunit.Abstractions;

namespace QuantumRayTracing.Tests.Engines;

/// <summary>
/// The full-state Grover search under a <see cref="DeviceNoiseModel"/> (<c>MeasureGroverBatchOnDevice</c> and the host's
/// readout flips) against the lookup circuit's exact density-matrix evolution (<see cref="LookupCircuitDensity"/>). The
/// simulator cannot be seeded, so every statistical check states its acceptance and false-failure probability.
/// </summary>
[Collection(QSharpCollection.Name)]
public class FullStateDeviceNoiseTests(FullStateFixture fixture, ITestOutputHelper output)
{
    private static readonly DeviceNoiseModel Device = new(2e-3, 3e-2, 0.02, 0.06);

    private FullStateEngine DeviceEngine(DeviceNoiseModel device, ulong seed) =>
        new(fixture.Engine.Pool, ownsPool: false, device: device, readoutRandom: new SeededRandom(seed));

    [Theory]
    [InlineData(2, new[] { 1 }, 2)]
    [InlineData(4, new[] { 0, 3 }, 1)]
    [InlineData(8, new[] { 5 }, 2)]
    [InlineData(8, new[] { 1, 4, 6, 7, 2 }, 1)]
    [InlineData(16, new[] { 3, 12, 9 }, 1)]
    public void DeviceCircuitRunsTheIdealCircuitsGates(int count, int[] marked, int iterations)
    {
        // The traced gates of the device batch at zero rates and of the ideal batch, kind by kind, and the evolution's
        // noise locations: one per one-qubit gate, one per qubit of each CZ and CCNOT.
        var request = new GroverRequest(new MarkedSet(count, marked), iterations);
        var device = Gates(FullStateEngine.DeviceBatchExpression(new DeviceNoiseModel(0, 0), [request]));
        Assert.Equal(Gates(FullStateEngine.BatchExpression([request])), device);
        var locations = LookupCircuitDensity.LocationsByKind(request.Marked, iterations);
        Assert.Equal(locations[(int)LookupCircuitDensity.GateKind.OneQubit], device.Where(g => Arity(g.Key) == 1).Sum(g => g.Value));
        Assert.Equal(locations[(int)LookupCircuitDensity.GateKind.MultiQubit], device.Where(g => Arity(g.Key) > 1).Sum(g => Arity(g.Key) * g.Value));
    }

    [Fact]
    public void MarkedProbabilityFollowsTheDensityEvolutionAndNeitherControl()
    {
        // N = 8, one and three marked, r = 1 and 2, 3,000 shots per row under p1 = 2e-3, p2 = 3e-2, readout P0 = 0.02, P1 = 0.06.
        // Each row's share of marked read indices lies within 4 binomial standard errors of the evolution (two-sided
        // false-failure 6.3e-5 per row, 2.5e-4 for the four, whatever the shots). Each negative control must miss at least one
        // row by more than 4 of its own standard errors: the evolution without the readout error (0.538 and 0.468 against the
        // device model's 0.473 and 0.414 at t = 1; σ ≈ 0.009, so it stays inside both rows with probability 2e-5) and with p2
        // after every gate (0.350 and 0.263 at t = 1, over 13σ off: never).
        const int shots = 3_000;
        (int[] Marked, int Iterations)[] rows = [([5], 1), ([5], 2), ([1, 4, 6], 1), ([1, 4, 6], 2)];
        var sets = rows.Select(r => new MarkedSet(8, r.Marked)).ToArray();
        using var engine = DeviceEngine(Device, seed: 11);
        var read = engine.Measure(rows.SelectMany((r, k) => Enumerable.Repeat(new GroverRequest(sets[k], r.Iterations), shots)).ToArray());
        var p2 = NoiseModel.Depolarizing(Device.TwoQubit);
        var models = new (string Name, CircuitRates Rates)[]
        {
            ("device model", CircuitRates.Of(Device)),
            ("without readout error", CircuitRates.Of(Device.WithoutReadout())),
            ("p2 after every gate", new CircuitRates(p2, p2, NoiseModel.None, Device.ReadZeroAsOne, Device.ReadOneAsZero)),
        };
        var gaps = new double[models.Length];
        for (var k = 0; k < rows.Length; k++)
        {
            var measured = read.Skip(k * shots).Take(shots).Count(i => i < 8 && sets[k].Contains(i)) / (double)shots;
            var line = $"t = {rows[k].Marked.Length}, r = {rows[k].Iterations}: measured {measured:0.0000}";
            for (var m = 0; m < models.Length; m++)
            {
                var p = LookupCircuitDensity.MarkedProbabilities(sets[k], rows[k].Iterations, models[m].Rates)[rows[k].Iterations];
                var errors = Math.Abs(measured - p) / Math.Sqrt(p * (1 - p) / shots);
                gaps[m] = Math.Max(gaps[m], errors);
                line += $"; {models[m].Name} {p:0.0000} ({errors:0.0} SE)";
                if (m == 0) Assert.True(errors <= 4, $"{line}: more than 4 standard errors from the evolution under the {Device}");
            }
            output.WriteLine(line);
        }
        for (var m = 1; m < models.Length; m++)
            Assert.True(gaps[m] > 4, $"the evolution {models[m].Name} fits every row (largest gap {gaps[m]:0.0} standard errors)");
    }

    [Fact]
    public void ScheduleStopsAtTheFirstReadMarkedIndex()
    {
        // Noiseless gates, a readout error of 0.25 on every bit: at N = 8, t = 1, r = 1 the index is marked with probability
        // 0.78 but read correctly only with 0.75³ = 0.42, so a stop decided on the measured index would often end a schedule
        // on an unmarked read index, or run on past a marked one; 150 schedules of 5 runs each must hold neither.
        var marked = new MarkedSet(8, [5]);
        var schedules = Enumerable.Range(0, 150).Select(_ => (IReadOnlyList<GroverRequest>)Enumerable.Repeat(new GroverRequest(marked, 1), 5).ToArray()).ToArray();
        using var engine = DeviceEngine(new DeviceNoiseModel(0, 0, 0.25, 0.25), seed: 5);
        var outcomes = engine.MeasureSchedules(schedules);
        foreach (var runs in outcomes)
        {
            Assert.All(runs[..^1], i => Assert.False(marked.Contains(i), $"schedule [{string.Join(", ", runs)}] ran on past a marked read index"));
            Assert.True(marked.Contains(runs[^1]) || runs.Length == 5, $"schedule [{string.Join(", ", runs)}] stopped on an unmarked read index");
        }
        // Both kinds of schedule occur (each fails to with probability below 1e-20), so the checks above were exercised.
        Assert.Contains(outcomes, runs => runs.Length > 1);
        Assert.Contains(outcomes, runs => runs.Length < 5);
        Assert.Equal(outcomes.Sum(runs => (long)runs.Length), engine.GroverRuns);
    }

    [Fact]
    public void SameSeedAndMeasuredIndicesGiveTheSameReadIndices()
    {
        // The engine reads each measured index with ReadoutFlips.ReadBits in request order: replayed on the same measured
        // indices, the same seed gives the same read indices and another seed other ones.
        var measured = Enumerable.Range(0, 2000).Select(k => k * 5 % 8).ToArray();
        int[] Read(ulong seed)
        {
            var flips = new ReadoutFlips(Device, new SeededRandom(seed));
            return measured.Select(i => flips.ReadBits(i, 3)).ToArray();
        }
        Assert.Equal(Read(11), Read(11));
        Assert.NotEqual(Read(11), Read(12));
        Assert.NotEqual(measured, Read(11));
    }

    [Fact]
    public void DeviceModelBesidePauliNoiseIsRefused() =>
        Assert.Throws<ArgumentException>(() => new FullStateEngine(fixture.Engine.Pool, ownsPool: false, noise: NoiseModel.Depolarizing(1e-3), device: Device, readoutRandom: new SeededRandom(1)));

    [Fact]
    public void ReadoutErrorNeedsTheSeededGenerator() =>
        Assert.Throws<ArgumentException>(() => new FullStateEngine(fixture.Engine.Pool, ownsPool: false, device: Device));

    [Fact]
    public void CountNotAPowerOfTwoIsRefusedByHostAndCircuit()
    {
        using var engine = DeviceEngine(Device, seed: 1);
        var request = new GroverRequest(new MarkedSet(6, [2]), 1);
        Assert.Contains("N = 6", Assert.Throws<ArgumentException>(() => engine.Measure([request])).Message);
        var failure = Assert.Throws<QSharpException>(() => fixture.Engine.Pool.ForEach([FullStateEngine.DeviceBatchExpression(Device, [request])], (e, bridge) => bridge.Run(e)));
        Assert.Contains("power of two", failure.Message);
    }

    /// <summary>The traced circuit's native gates by name (H, X, Z, CZ, CCX, …), measurement and reset included.</summary>
    private Dictionary<string, long> Gates(string expression)
    {
        var gates = new Dictionary<string, long>();
        fixture.Engine.Pool.ForEach([expression], (e, bridge) =>
        {
            foreach (var (kind, count) in bridge.Circuit(e)["native"]!["gates"]!.AsObject()) gates[kind] = count!.GetValue<long>();
        });
        return gates;
    }

    private static int Arity(string gate) => gate.TakeWhile(c => c == 'C').Count() + 1;
}
