using QuantumRayTracing.Experiments;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Scenes.Generation;
using QuantumRayTracing.Search;
using QuantumRayTracing.Supersampling;
using QuantumRayTracing.Tests.Engines;
using QuantumRayTracing.Tests.Statistics;

namespace QuantumRayTracing.Tests.Noise;

/// <summary>
/// The noise model against the noisy full-state simulator. The simulator cannot be seeded, so every check is
/// statistical: each comparison of the approximation allows its stated tolerance δ = <see cref="NoiseReport.ModelTolerance"/>
/// plus z = 4.89 binomial standard errors (false-failure at most 1e-6 per comparison, 1e-5 per test).
/// </summary>
[Collection(QSharpCollection.Name)]
public class NoisySimulatorTests(FullStateFixture fixture)
{
    private static readonly NoiseModel[] Levels = [NoiseModel.Depolarizing(1e-3), NoiseModel.Depolarizing(3e-3), NoiseModel.Depolarizing(1e-2)];

    private BridgePool Pool => fixture.Engine.Pool;

    [Theory]
    [InlineData(2, new[] { 1 })]
    [InlineData(4, new[] { 0 })]
    [InlineData(8, new[] { 1, 2, 5 })]
    [InlineData(8, new[] { 0, 1, 2, 4, 5, 6, 7 })]
    [InlineData(16, new int[0])]
    [InlineData(64, new[] { 17, 40 })]
    public void LookupNoiseLocationsMatchTheExtractedCircuit(int count, int[] marked)
    {
        var set = new MarkedSet(count, marked);
        // MeasureGroverSearch iterates with the complement when more than half is marked; the traced iteration takes the set it is given.
        var oracleSet = 2 * marked.Length > count ? Enumerable.Range(0, count).Except(marked).ToArray() : marked;
        var list = oracleSet.Length == 0 ? "[0, size = 0]" : $"[{string.Join(", ", oracleSet)}]";
        long traced = 0, outside = 0;
        Pool.ForEach([0], (_, bridge) =>
        {
            traced = NoiseLocations.FromCircuit(bridge.Circuit($"QuantumRayTracing.Search.ApplyGroverIterationOnNewRegisters({count}, {list})")["native"]!.AsObject());
            outside = NoiseLocations.FromCircuit(bridge.Circuit($"QuantumRayTracing.Search.MeasureGroverSearch({count}, {list}, 0)")["native"]!.AsObject());
        });
        Assert.Equal(traced, NoiseLocations.LookupIteration(set));
        Assert.Equal(outside, NoiseLocations.PrepareAndMeasure(count));
    }

    [Fact]
    public void ApproximationAgreesWithTheNoisySimulator()
    {
        // Lookup oracle at two sizes and the gate-level oracle on the device experiment's ray, three noise levels each.
        var device = DeviceExperimentScene.Ray();
        GroverRequest[] requests =
        [
            new(new MarkedSet(16, [3]), 3),
            new(new MarkedSet(64, [17]), 6),
            new(device.Table.Marked(device.Window), 1, device),
        ];
        var rows = NoiseCheck.Measure(Pool, requests, Levels, shots: 500);
        Assert.Equal(9, rows.Count);
        foreach (var row in rows)
        {
            var model = row.Predicted(DepolarizingApproximation.Default);
            var bound = NoiseReport.ModelTolerance + NoiseCheck.Z * row.StandardError(DepolarizingApproximation.Default);
            Assert.True(Math.Abs(row.Observed - model) <= bound,
                $"{row.Oracle} N = {row.Count}, t = {row.Marked}, r = {row.Iterations}, {row.Noise}: observed {row.Observed:0.000}, model {model:0.000}, allowed ±{bound:0.000}");
        }
        // The model is not vacuous here: the ideal probability lies outside every acceptance region at p = 1e-2.
        foreach (var row in rows.Where(r => r.Noise.PerGate == 1e-2))
            Assert.True(Math.Abs(row.Observed - GroverProbability.OfMarked(row.Request)) > NoiseReport.ModelTolerance + NoiseCheck.Z * row.StandardError(DepolarizingApproximation.Default));
    }

    [Fact]
    public void MarkedShareFallsMonotonicallyWithNoise()
    {
        // N = 16, t = 1, r = 3: about 0.96, 0.70, 0.35 and 0.10 at p = 0, 3e-3, 1e-2, 3e-2; neighbours are at
        // least 0.25 apart, over 8 standard errors at 600 shots, so a reversal fails only on a broken noise path.
        var request = new GroverRequest(new MarkedSet(16, [3]), 3);
        var shares = new List<double>();
        foreach (var p in new[] { 0, 3e-3, 1e-2, 3e-2 })
        {
            using var engine = new FullStateEngine(Pool, ownsPool: false, noise: NoiseModel.Depolarizing(p));
            var measured = engine.Measure(Enumerable.Repeat(request, 600).ToArray());
            shares.Add(measured.Count(request.Marked.Contains) / 600.0);
        }
        for (var k = 1; k < shares.Count; k++)
            Assert.True(shares[k] < shares[k - 1], $"share of marked outcomes rose with noise: {string.Join(", ", shares)}");
    }

    [Fact]
    public void QubitLossReadsZeroAndLowersTheMarkedShare()
    {
        // Ideal P(marked) = 0.96 at N = 16, t = 1, r = 3; with 2 % loss per operation over ~150 locations most
        // runs lose a qubit. Every readout still lies in the register, and the share falls far below the
        // ideal acceptance interval (false-failure 1e-8).
        var request = new GroverRequest(new MarkedSet(16, [3]), 3);
        using var engine = new FullStateEngine(Pool, ownsPool: false, noise: new NoiseModel(0, 0, 0, 0.02));
        var measured = engine.Measure(Enumerable.Repeat(request, 400).ToArray());
        Assert.All(measured, i => Assert.InRange(i, 0, 15));
        var (low, _) = StatisticalBounds.BinomialInterval(GroverProbability.OfMarked(request), 400);
        Assert.True(measured.Count(request.Marked.Contains) < low);
    }

    [Fact]
    public void SupersamplingCircuitsRunUnderNoise()
    {
        // A coin whose every amplitude is 0 never shows heads on an ideal machine; under p = 0.1 per gate,
        // and with qubit loss, it does. 200 flips: the chance of no heads at all is negligible.
        using var noisy = new FullStateSupersamplingEngine(Pool, ownsPool: false, noise: new NoiseModel(0.05, 0, 0.05, 0.01));
        var heads = noisy.FlipCoins([new CoinRequest(CoinKind.Mean, [0.0, 0.0, 0.0, 0.0], 1, 200)]);
        Assert.InRange(heads[0], 1, 200);
        using var ideal = new FullStateSupersamplingEngine(Pool, ownsPool: false);
        Assert.Equal(0, ideal.FlipCoins([new CoinRequest(CoinKind.Mean, [0.0, 0.0, 0.0, 0.0], 1, 200)])[0]);
    }
}
