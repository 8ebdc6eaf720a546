using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Tests.Estimation;

public class MlaeScheduleTests
{
    [Fact]
    public void DefaultScheduleGrowsByOneAndAHalf()
    {
        // round(1.5^j) half away from zero: 1, 1.5 → 2, 2.25 → 2 (dropped), 3.375 → 3, 5.06 → 5, 7.59 → 8, 11.4 → 11, 17.1 → 17, 25.6 → 26, 38.4 → 38, 57.7 → 58.
        Assert.Equal([0, 1, 2, 3, 5, 8, 11, 17, 26, 38, 58], MlaeSchedule.Default.Iterations(10));
        Assert.Equal([0, 1, 2, 4, 8, 16], MlaeSchedule.Doubling.Iterations(5));
        Assert.Equal([0], MlaeSchedule.Default.Iterations(0));
    }

    [Fact]
    public void QueriesPerShotWeighTheBoostedLevelsTwice()
    {
        // m = 0, 1 twice (2·1 + 2·3), then 5, 7 for m = 2, 3.
        Assert.Equal(20, MlaeSchedule.Default.QueriesPerShot(3));
        Assert.Equal(1 + 3 + 5 + 9, MlaeSchedule.Doubling.QueriesPerShot(3));
        Assert.Equal(1, MlaeSchedule.Default.QueriesPerShot(0));
    }

    [Theory]
    [InlineData(240, 3)]   // 20 per shot leaves 12 flips; K = 4 costs 31, 7 flips: below 8
    [InlineData(19, 0)]
    [InlineData(3200, 10)] // K = 10 costs 353: 9 flips; K = 11 adds 2·86 + 1 = 173: 6 flips
    public void DefaultLevelsKeepEightFlipsPerLevel(long queries, int levels) =>
        Assert.Equal(levels, MlaeSchedule.Default.DefaultLevels(queries));

    [Theory]
    [InlineData(240, 3)]
    [InlineData(241, 4)]
    [InlineData(3200, 10)]
    [InlineData(1, 0)]
    public void FlipsSpendTheBudgetExactly(long queries, int levels)
    {
        var mlae = new MaximumLikelihoodEstimator(queries, levels);
        Assert.Equal(queries, mlae.Iterations.Zip(mlae.Flips).Sum(l => (long)l.Second * (1 + 2 * l.First)));
        // Boosted levels get twice the flips of the rest, the m = 0 level at least that.
        if (levels >= 2)
        {
            Assert.Equal(2 * mlae.Shots, mlae.Flips[1]);
            Assert.True(mlae.Flips[0] >= 2 * mlae.Shots);
            Assert.All(mlae.Flips.Skip(2), f => Assert.Equal(mlae.Shots, f));
        }
    }
}
