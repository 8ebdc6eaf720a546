using QuantumRayTracing.Engines;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Engines;
using QuantumRayTracing.Tests.Statistics;

namespace QuantumRayTracing.Tests.Noise;

/// <summary>The analytic side of the noise model: no bridge, seeded.</summary>
public class DepolarizingApproximationTests
{
    private static GroverRequest Request(int count, int[] marked, int iterations) => new(new MarkedSet(count, marked), iterations);

    [Fact]
    public void NoiselessEngineDrawsExactlyAsBefore()
    {
        // The ideal model must take today's path draw for draw: same seed, same outcomes.
        var requests = GroverCase.Hard.SelectMany(c => Enumerable.Repeat(c.Request, 50)).ToArray();
        var plain = new AnalyticEngine(new SeededRandom(11)).Measure(requests);
        var noiseless = new AnalyticEngine(new SeededRandom(11), NoiseModel.None).Measure(requests);
        Assert.Equal(plain, noiseless);
    }

    [Theory]
    [InlineData(64, new[] { 17 }, 6)]
    [InlineData(16, new[] { 3, 9 }, 2)]
    [InlineData(8, new[] { 1, 2, 5 }, 1)]
    public void MarkedProbabilityFallsMonotonicallyWithNoiseTowardsUniform(int count, int[] marked, int iterations)
    {
        var request = Request(count, marked, iterations);
        var previous = GroverProbability.OfMarked(request);
        Assert.Equal(previous, DepolarizingApproximation.Default.MarkedProbability(NoiseModel.None, request), 12);
        foreach (var p in new[] { 1e-5, 1e-4, 1e-3, 3e-3, 1e-2, 3e-2, 0.1 })
        {
            var next = DepolarizingApproximation.Default.MarkedProbability(NoiseModel.Depolarizing(p), request);
            Assert.True(next < previous, $"p = {p}: {next} is not below {previous}");
            previous = next;
        }
        // At p = 0.9 every location is almost surely hit: the run reads uniformly, t/N.
        Assert.Equal((double)marked.Length / count, DepolarizingApproximation.Default.MarkedProbability(NoiseModel.Depolarizing(0.9), request), 6);
    }

    [Fact]
    public void NoisyAnalyticEngineSamplesTheModel()
    {
        // 20000 samples per case; each count inside its binomial acceptance interval at false-failure 1e-8.
        var noise = NoiseModel.Depolarizing(3e-3);
        var engine = new AnalyticEngine(new SeededRandom(5), noise);
        const int shots = 20000;
        foreach (var request in new[] { Request(64, [17], 6), Request(16, [3, 9], 2), Request(12, [2, 9], 1) })
        {
            var measured = engine.Measure(Enumerable.Repeat(request, shots).ToArray());
            var readable = 1 << SearchRegisters.For(request.Marked.Count).IndexQubits;
            Assert.All(measured, i => Assert.InRange(i, 0, readable - 1));
            var hits = measured.Count(request.Marked.Contains);
            StatisticalBounds.AssertBinomial(hits, DepolarizingApproximation.Default.MarkedProbability(noise, request), shots, $"analytic under {noise}, N = {request.Marked.Count}");
        }
    }

    [Fact]
    public void NoiseLocationsOfTheLookupRunAreCountedPerOracleIndex()
    {
        // N = 64: the phase on the all-ones state of 6 index qubits is a ladder of 4 CCX, one CZ and the 4 CCX
        // undone (8 · 3 + 2 = 26 locations); the diffusion adds 12 H and 12 X; index 17's all-ones pattern is
        // 4 X there and 4 back.
        Assert.Equal(26, NoiseLocations.PhaseToAllOnes(6));
        Assert.Equal(12 + 12 + 26 + 26 + 8, NoiseLocations.LookupIteration(new MarkedSet(64, [17])));
        // More than half marked: the complement is the oracle set, as in the Q# operation.
        Assert.Equal(NoiseLocations.LookupIteration(new MarkedSet(8, [3])), NoiseLocations.LookupIteration(new MarkedSet(8, [0, 1, 2, 4, 5, 6, 7])));
    }

    [Fact]
    public void QSearchTakesAReadoutPastNAsAMissWithoutATest()
    {
        // N = 12 has 4 index qubits: a noisy machine can read 12..15, which names no primitive.
        var search = new QSearch(new MarkedSet(12, [5]), new QSearchSchedule(12), new SeededRandom(2));
        search.NextRequest();
        search.Observe(14);
        Assert.Null(search.Found);
        Assert.Equal(0, search.Cost.ClassicalTests);
        search.NextRequest();
        search.Observe(5);
        Assert.Equal(5, search.Found);
        Assert.Equal(1, search.Cost.ClassicalTests);
        var other = new QSearch(new MarkedSet(12, [5]), new QSearchSchedule(12), new SeededRandom(2));
        other.NextRequest();
        Assert.Throws<ArgumentOutOfRangeException>(() => other.Observe(16));
    }
}
