using System.Globalization;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;
using QuantumRayTracing.Tests.Engines;
using QuantumRayTracing.Tests.Statistics;

namespace QuantumRayTracing.Tests.Noise;

/// <summary>
/// The device noise model (<see cref="DeviceNoise"/>) against the noisy full-state simulator, where the Q# device circuits
/// set each gate's rate themselves and the host applies the readout error: the simulator cannot be seeded, so every check
/// states its acceptance and false-failure probability.
/// </summary>
[Collection(QSharpCollection.Name)]
public class DeviceNoiseSimulatorTests(FullStateFixture fixture)
{
    private BridgePool Pool => fixture.Engine.Pool;

    private (long OneQubit, long TwoQubit) TracedGates(string expression)
    {
        var (one, two) = (0L, 0L);
        Pool.ForEach([expression], (e, bridge) =>
        {
            foreach (var (kind, count) in bridge.Circuit(e)["native"]!["gates"]!.AsObject())
            {
                var qubits = kind.TakeWhile(c => c == 'C').Count() + (kind.TrimStart('C').TrimEnd('†') == "SWAP" ? 2 : 1);
                if (qubits == 1) one += count!.GetValue<long>();
                else two += count!.GetValue<long>();
            }
        });
        return (one, two);
    }

    private static string D(double value) => value.ToString("0.0###############", CultureInfo.InvariantCulture);

    [Theory]
    [InlineData(0)]
    [InlineData(1)]
    [InlineData(5)]
    public void DirectCoinGatesMatchTheExtractedCircuit(int iterations) =>
        Assert.Equal(DeviceCircuitGates.DirectCoin(iterations), TracedGates($"QuantumRayTracing.Supersampling.CountDirectCoinHeadsOnDevice(0.0, {D(0.6)}, {iterations}, 1)"));

    [Theory]
    [InlineData(1)]
    [InlineData(2)]
    [InlineData(3)]
    [InlineData(4)]
    public void DirectQssGatesMatchTheExtractedCircuit(int counterBits) =>
        Assert.Equal(DeviceCircuitGates.DirectQss(counterBits), TracedGates($"QuantumRayTracing.Supersampling.MeasureDirectQssOnDevice(0.0, 0.0, {D(0.6)}, {counterBits})"));

    [Fact]
    public void NoiselessDirectQssReadsAsTheExactQssDistribution()
    {
        // f = 0.3, t = 3, 3000 runs: Pearson's chi-square against the Fejér-kernel distribution at false-failure 1e-8.
        using var engine = new FullStateCoinEngine(Pool, ownsPool: false);
        var readouts = engine.ReadCounters([new QssRequest([Math.Sqrt(0.3)], 3, 3000, CoinKind.Direct)])[0];
        var counts = new int[8];
        foreach (var y in readouts) counts[y]++;
        StatisticalBounds.AssertFits(counts, CoinProbability.QssReadout(0.3, 3), "QSS on the single-qubit coin, f = 0.3, t = 3");
    }

    [Fact]
    public void DirectCoinModelWithReadoutIsExactAndReadoutCannotBeLeftOut()
    {
        // The single-qubit model is exact, readout included: 20,000 flips per case within the binomial interval at false-failure
        // 1e-8 (3 checks). At f = ½ and m = 0 only the readout moves the head from ½ (to 0.02 + 0.86/2 = 0.45): the model
        // without readout predicts ½, 14 standard errors off, and must fall outside the interval.
        var device = new DeviceNoiseModel(1e-2, 0, 0.02, 0.12);
        using var engine = new FullStateCoinEngine(Pool, ownsPool: false, device: device, readoutRandom: new SeededRandom(3));
        (double Amplitude, int Iterations)[] cases = [(Math.Sqrt(0.5), 0), (Math.Sqrt(0.5), 4), (Math.Sqrt(0.1), 8)];
        const int flips = 20_000;
        var heads = engine.FlipCoins(cases.Select(c => new CoinRequest(CoinKind.Direct, [c.Amplitude], c.Iterations, flips)).ToArray());
        for (var k = 0; k < cases.Length; k++)
            StatisticalBounds.AssertBinomial(heads[k], DeviceNoise.DirectCoinHeadProbability(device, cases[k].Amplitude, cases[k].Iterations), flips,
                $"direct coin f = {cases[k].Amplitude * cases[k].Amplitude:0.##}, m = {cases[k].Iterations}, {device}");
        var (low, high) = StatisticalBounds.BinomialInterval(DeviceNoise.DirectCoinHeadProbability(device.WithoutReadout(), Math.Sqrt(0.5), 0), flips);
        Assert.True(heads[0] < low || heads[0] > high, $"{heads[0]} heads of {flips} fit the model without readout, [{low}, {high}]");
    }

    [Fact]
    public void DirectQssApproximationAgreesAndTwoQubitNoiseCannotBeLeftOut()
    {
        // QSS on the single-qubit coin, t = 2 (3 qubits, 20 two-qubit gates), under p1 = 1e-3, p2 = 5e-2 and readout 0.02, 0.08;
        // 3000 runs per mean. Each readout's share lies within δ = 0.03 (the global depolarizing weight's own error on this circuit)
        // plus z = 4.89 binomial standard errors of the model (false-failure 1e-6 per comparison, 8 comparisons). The model
        // with ideal two-qubit gates must miss some share by more than that bound.
        const double delta = 0.03, z = 4.8916;
        var device = new DeviceNoiseModel(1e-3, 5e-2, 0.02, 0.08);
        var noTwoQubit = new DeviceNoiseModel(1e-3, 0, 0.02, 0.08);
        using var engine = new FullStateCoinEngine(Pool, ownsPool: false, device: device, readoutRandom: new SeededRandom(4));
        double[] means = [0.5, 0.1];
        const int shots = 3000;
        var readouts = engine.ReadCounters(means.Select(f => new QssRequest([Math.Sqrt(f)], 2, shots, CoinKind.Direct)).ToArray());
        var controlRejected = false;
        for (var k = 0; k < means.Length; k++)
        {
            var model = DeviceNoise.DirectQssReadout(device, Math.Sqrt(means[k]), 2);
            var control = DeviceNoise.DirectQssReadout(noTwoQubit, Math.Sqrt(means[k]), 2);
            for (var y = 0; y < 4; y++)
            {
                var observed = readouts[k].Count(v => v == y) / (double)shots;
                var bound = delta + z * Math.Sqrt(model[y] * (1 - model[y]) / shots);
                Assert.True(Math.Abs(observed - model[y]) <= bound, $"f = {means[k]}, y = {y}: observed {observed:0.000}, model {model[y]:0.000}, allowed ±{bound:0.000}");
                controlRejected |= Math.Abs(observed - control[y]) > bound;
            }
        }
        Assert.True(controlRejected, "the model with ideal two-qubit gates fits every readout share");
    }
}
