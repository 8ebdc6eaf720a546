using QuantumRayTracing.Experiments;

namespace QuantumRayTracing.Tests.Experiments;

public class NoiseBenchmarkTests
{
    [Fact]
    public void DistanceFromUniformRunsFromZeroToOneLessOneOverK()
    {
        Assert.Equal(0.75, NoiseBenchmark.TotalVariationFromUniform([0, 0, 1024, 0]), 12);
        Assert.Equal(0.0, NoiseBenchmark.TotalVariationFromUniform([256, 256, 256, 256]), 12);
        Assert.Equal(0.5, NoiseBenchmark.TotalVariationFromUniform([512, 0, 512, 0]), 12);
    }

    [Fact]
    public void RateAtDistanceInterpolatesLogLinearlyBetweenTheRatesAroundTheCrossing()
    {
        // One peak of share q over 4 cells is q − 1/4 from uniform: 0.5 at 1e-3 and 0.1 at 1e-1; 0.3 lies halfway,
        // at 1e-2 on the log scale.
        var runs = new[]
        {
            new NoiseBenchmark.DeviceRun(0, [0, 0, 1000, 0]),
            new NoiseBenchmark.DeviceRun(1e-3, [100, 100, 900, 100]),
            new NoiseBenchmark.DeviceRun(1e-1, [260, 260, 420, 260]),
        };
        Assert.Equal(0.5, runs[1].DistanceFromUniform, 12);
        Assert.Equal(0.1, runs[2].DistanceFromUniform, 12);
        Assert.Equal(1e-2, NoiseBenchmark.RateAtDistance(runs, 0.3)!.Value, 9);
        Assert.Null(NoiseBenchmark.RateAtDistance(runs, 0.05));
    }

    [Fact]
    public void UniformSamplingFloorFallsAsOneOverRootShots()
    {
        // 4 cells: 0.5 · 4 · sqrt(2/π) · sqrt(3/16 / n); at n = 1024 about 0.0216.
        Assert.Equal(0.0216, NoiseReport.UniformSamplingFloor(4, 1024), 4);
        Assert.Equal(2 * NoiseReport.UniformSamplingFloor(4, 4096), NoiseReport.UniformSamplingFloor(4, 1024), 12);
    }

    [Fact]
    public void CrossingIsWhereTheMarginTurnsNonNegativeLogLinearly()
    {
        // The margin depends only on the rate here: −1 at 1e-3, +1 at 1e-1, so it crosses 0 halfway, at 1e-2.
        var points = new[] { 0, 1e-4, 1e-3, 1e-1 }.Select(p => new NoisyRenderBenchmark.Point(p, null!)).ToArray();
        var sweep = new NoisyRenderBenchmark.Sweep("test", QuantumRayTracing.Noise.NoiseOracle.GateLevel, null!, points, []);
        Assert.Equal(1e-2, sweep.Crossing(p => p.PerGate switch { 1e-4 => double.NaN, 1e-3 => -1, _ => 1 })!.Value, 9);
        Assert.Null(sweep.Crossing(_ => -1));
        // Already lost at the lowest noisy rate: that rate.
        Assert.Equal(1e-4, sweep.Crossing(_ => 0)!.Value, 12);
    }
}
