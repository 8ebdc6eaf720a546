using QuantumRayTracing.Search;

namespace QuantumRayTracing.Tests.Search;

public class QSearchScheduleTests
{
    // The sets printed in the paper's table 6 (c = 1.8): round(c^l) from l = 0 while below ceil(sqrt N).
    [Theory]
    [InlineData(8, new[] { 1, 2 })]
    [InlineData(16, new[] { 1, 2, 3 })]
    [InlineData(32, new[] { 1, 2, 3 })]
    [InlineData(64, new[] { 1, 2, 3, 6 })]
    [InlineData(128, new[] { 1, 2, 3, 6, 10 })]
    [InlineData(256, new[] { 1, 2, 3, 6, 10 })]
    [InlineData(512, new[] { 1, 2, 3, 6, 10, 19 })]
    public void RoundRuleGivesTableSix(int count, int[] expected)
    {
        Assert.Equal(expected, new QSearchSchedule(count, 1.8, MSetRule.Round).Bounds);
    }

    // Algorithm 1 as printed: min(ceil(c^l), ceil(sqrt N)) from l = 1 until the cap is reached.
    [Theory]
    [InlineData(1, new[] { 1 })]
    [InlineData(8, new[] { 2, 3 })]
    [InlineData(64, new[] { 2, 4, 6, 8 })]
    [InlineData(512, new[] { 2, 4, 6, 11, 19, 23 })]
    public void CeilingRuleFollowsAlgorithmOne(int count, int[] expected)
    {
        Assert.Equal(expected, new QSearchSchedule(count, 1.8, MSetRule.Ceiling).Bounds);
    }

    [Theory]
    [InlineData(1, 1)]
    [InlineData(2, 2)]
    [InlineData(8, 3)]
    [InlineData(9, 3)]
    [InlineData(10, 4)]
    [InlineData(512, 23)]
    public void CeilSqrtIsExact(int n, int expected) => Assert.Equal(expected, QSearchSchedule.CeilSqrt(n));

    [Theory]
    [InlineData(1.0)]
    [InlineData(2.0)]
    [InlineData(double.NaN)]
    public void GrowthOutsideOpenIntervalIsRejected(double growth)
    {
        Assert.Throws<ArgumentOutOfRangeException>(() => new QSearchSchedule(8, growth));
    }
}
