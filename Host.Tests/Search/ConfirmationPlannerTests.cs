using QuantumRayTracing.Search;

namespace QuantumRayTracing.Tests.Search;

public sealed class ConfirmationPlannerTests
{
    private static double Miss(int n, int t, IEnumerable<int> runs)
    {
        var theta = Math.Asin(Math.Sqrt((double)t / n));
        return runs.Aggregate(1.0, (m, r) => m * Math.Pow(Math.Cos((2 * r + 1) * theta), 2));
    }

    [Theory]
    [InlineData(64, 8, 0.025)]
    [InlineData(64, 8, 0.4)]
    [InlineData(512, 8, 0.025)]
    [InlineData(100, 4, 0.1)]
    public void ChosenListMeetsTheBoundForEveryT(int n, int maxT, double bound)
    {
        var plan = ConfirmationPlanner.Cheapest(n, maxT, bound);
        Assert.NotNull(plan);
        Assert.True(plan.IsFixed);
        for (var t = 1; t <= maxT; t++)
            Assert.True(Miss(n, t, plan.Bounds) <= bound, $"t = {t}: miss {Miss(n, t, plan.Bounds)} above {bound} with {plan}");
    }

    [Fact]
    public void NoShorterOrCheaperListOfOneOrTwoRunsBeatsIt()
    {
        // Independent check by brute force over every list of one or two runs at N = 64, t ≤ 8, miss ≤ 0.4.
        const int n = 64, maxT = 8;
        const double bound = 0.4;
        var plan = ConfirmationPlanner.Cheapest(n, maxT, bound)!;
        var cost = plan.Bounds.Sum(r => r + 2);
        for (var a = 1; a <= 8; a++)
            for (var b = 0; b <= 8; b++)
            {
                int[] runs = b == 0 ? [a] : [a, b];
                if (Enumerable.Range(1, maxT).All(t => Miss(n, t, runs) <= bound))
                    Assert.True(cost <= runs.Sum(r => r + 2), $"{string.Join(",", runs)} is cheaper than {plan}");
            }
    }

    [Fact]
    public void AtN64TheProblemStatementsListIsMatchedOrBeaten()
    {
        // r = 2, 2, 5 meets 2.5% for t ≤ 8 at N = 64 (it costs 15 queries): the planner must not do worse.
        Assert.True(Enumerable.Range(1, 8).All(t => Miss(64, t, [2, 2, 5]) <= 0.025));
        var plan = ConfirmationPlanner.Cheapest(64, 8, 0.025)!;
        Assert.True(plan.Bounds.Sum(r => r + 1) <= 15, plan.ToString());
    }

    [Fact]
    public void ImpossibleBoundGivesNoList() =>
        // At N = 4 a run with r = 1 hits t = 1 surely (sin²(3θ) = 1) but r ≤ ceil(sqrt 4) = 2 cannot serve t = 2 (θ = π/4: cos²(3π/4) = 1/2, cos²(5π/4) = 1/2).
        Assert.Null(ConfirmationPlanner.Cheapest(4, 2, 0.01));
}
