using QuantumRayTracing.Metrics;

namespace QuantumRayTracing.Tests.Metrics;

public class CorrelationTests
{
    [Fact]
    public void PearsonOnHandWorkedData()
    {
        Assert.Equal(1, Correlation.Pearson([1, 2, 3, 4], [2, 4, 6, 8]), 12);
        Assert.Equal(-1, Correlation.Pearson([1, 2, 3, 4], [8, 6, 4, 2]), 12);
        // Means 2 and 2: Σ dx·dy = 1, Σ dx² = Σ dy² = 2, so r = 1/2.
        Assert.Equal(0.5, Correlation.Pearson([1, 2, 3], [1, 3, 2]), 12);
        Assert.True(double.IsNaN(Correlation.Pearson([1, 1, 1], [1, 2, 3])));
    }

    [Fact]
    public void SpearmanRanksTiesByTheirMeanRank()
    {
        Assert.Equal([1.5, 1.5, 3, 4], Correlation.Ranks([7, 7, 9, 10]));
        Assert.Equal([3, 1, 2], Correlation.Ranks([0.9, 0.1, 0.5]));
        // Monotone but not linear: ρ = 1 where r < 1.
        Assert.Equal(1, Correlation.Spearman([1, 2, 3, 4], [1, 10, 100, 1000]), 12);
        Assert.True(Correlation.Pearson([1, 2, 3, 4], [1, 10, 100, 1000]) < 0.9);
    }
}
