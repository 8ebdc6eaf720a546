using QuantumRayTracing.Noise;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;
using QuantumRayTracing.Tests.Statistics;

namespace QuantumRayTracing.Tests.Noise;

public class DeviceNoiseModelTests
{
    [Theory]
    [InlineData("1q=1e-3,2q=5e-2", null, 1e-3, 5e-2, 0, 0)]
    [InlineData("2q=0.05", "0.03", 0, 0.05, 0.03, 0.03)]
    [InlineData(null, "0.02,0.1", 0, 0, 0.02, 0.1)]
    [InlineData(" 1q = 0.01 ", "0.0, 0.2", 0.01, 0, 0, 0.2)]
    public void ParsesGateRatesAndReadout(string? gates, string? readout, double one, double two, double p0, double p1)
    {
        var model = DeviceNoiseModel.Parse(gates, readout, out var problem);
        Assert.Null(problem);
        Assert.Equal(new DeviceNoiseModel(one, two, p0, p1), model);
    }

    [Theory]
    [InlineData("3q=0.1", null, "--device-noise: '3q=0.1' is not 1q=P or 2q=P")]
    [InlineData("1q=0.1,2q", null, "--device-noise: '2q' is not 1q=P or 2q=P")]
    [InlineData("1q=-0.1", null, "--device-noise: 1q = -0.1 is not a probability in [0, 1]")]
    [InlineData("2q=abc", null, "--device-noise: 2q: 'abc' is not a number")]
    [InlineData(null, "0.1,0.2,0.3", "--readout-error: '0.1,0.2,0.3' is neither one probability P nor two, P0,P1")]
    [InlineData(null, "0.5", "--readout-error: P0 + P1 = 1 must stay below 1 (the readout would carry no information)")]
    [InlineData(null, "1.5,0", "--readout-error: P0 = 1.5 is not a probability in [0, 1]")]
    public void RejectsWithOneLineNamingTheOption(string? gates, string? readout, string expected)
    {
        Assert.Null(DeviceNoiseModel.Parse(gates, readout, out var problem));
        Assert.Equal(expected, problem);
    }

    [Fact]
    public void ReadBitsFlipsEachBitByItsOwnError()
    {
        // Two bits, the value 2 = (bit 1 set, bit 0 clear) for certain: reading it as v takes bit 0 (a 0) to v's bit 0 with
        // P0 or 1 − P0, and bit 1 (a 1) to v's bit 1 with 1 − P1 or P1.
        var device = new DeviceNoiseModel(0, 0, 0.1, 0.3);
        var read = DeviceNoise.ReadBits(device, [0, 0, 1, 0], 2);
        Assert.Equal(0.9 * 0.3, read[0], 12);
        Assert.Equal(0.1 * 0.3, read[1], 12);
        Assert.Equal(0.9 * 0.7, read[2], 12);
        Assert.Equal(0.1 * 0.7, read[3], 12);
    }

    [Fact]
    public void ReadoutBiasesTheUnamplifiedCoinAtOneHalfWhereDepolarizingCannot()
    {
        // f = ½, m = 0: depolarizing noise leaves the head at ½ exactly; P0 = 0.02, P1 = 0.1 read it at 0.02 + 0.88 · ½ = 0.46.
        var gatesOnly = new DeviceNoiseModel(0.05, 0);
        var withReadout = new DeviceNoiseModel(0.05, 0, 0.02, 0.1);
        Assert.Equal(0.5, DeviceNoise.DirectCoinHeadProbability(gatesOnly, Math.Sqrt(0.5), 0), 12);
        Assert.Equal(0.46, DeviceNoise.DirectCoinHeadProbability(withReadout, Math.Sqrt(0.5), 0), 12);
    }

    [Fact]
    public void ReadoutFlipsSampleTheReadoutError()
    {
        // 200,000 true heads and 200,000 true tails: each read count within the binomial interval at false-failure 1e-8.
        var device = new DeviceNoiseModel(0, 0, 0.03, 0.12);
        var flips = new ReadoutFlips(device, new SeededRandom(5));
        StatisticalBounds.AssertBinomial(flips.ReadHeads(200_000, 200_000), 1 - 0.12, 200_000, "heads kept");
        StatisticalBounds.AssertBinomial(flips.ReadHeads(0, 200_000), 0.03, 200_000, "tails read as heads");
        var ones = Enumerable.Range(0, 50_000).Select(_ => flips.ReadBits(0b01, 2)).ToArray();
        StatisticalBounds.AssertBinomial(ones.Count(v => (v & 1) == 0), 0.12, ones.Length, "bit 0 (a 1) read as 0");
        StatisticalBounds.AssertBinomial(ones.Count(v => (v & 2) != 0), 0.03, ones.Length, "bit 1 (a 0) read as 1");
    }

    [Fact]
    public void AnalyticEngineIsReproducibleAndRefusesTheSubpixelCoins()
    {
        var device = new DeviceNoiseModel(1e-2, 5e-2, 0.02, 0.1);
        CoinRequest[] coins = [new(CoinKind.Direct, [0.6], 3, 500), new(CoinKind.Direct, [0.2], 0, 500)];
        QssRequest[] qss = [new([0.7], 2, 50, CoinKind.Direct)];
        IReadOnlyList<int> Heads() => new AnalyticCoinEngine(new SeededRandom(9), device: device).FlipCoins(coins);
        Assert.Equal(Heads(), Heads());
        var engine = new AnalyticCoinEngine(new SeededRandom(9), device: device);
        Assert.Equal(new AnalyticCoinEngine(new SeededRandom(9), device: device).ReadCounters(qss)[0], engine.ReadCounters(qss)[0]);
        var error = Assert.Throws<ArgumentException>(() => engine.FlipCoins([new CoinRequest(CoinKind.Mean, [0.5, 0.5], 1, 10)]));
        Assert.Equal(AnalyticCoinEngine.DeviceNeedsDirectCoins, error.Message);
        Assert.Throws<ArgumentException>(() => new AnalyticCoinEngine(new SeededRandom(1), NoiseModel.Depolarizing(1e-3), device: device));
    }
}
