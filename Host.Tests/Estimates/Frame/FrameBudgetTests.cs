using QuantumRayTracing.Estimates;

namespace QuantumRayTracing.Tests.Estimates;

/// <summary>The budget's split over a frame's runs and the parallel runtime's schedule.</summary>
public sealed class FrameBudgetTests
{
    [Theory]
    [InlineData(0.01, 1)]
    [InlineData(0.01, 113_108)]
    [InlineData(1e-6, 7)]
    [InlineData(0.5, 1_000_000_000)]
    public void EachRunGetsTheFrameBudgetOverTheRuns(double frame, long runs)
    {
        var budget = new FrameBudget(frame, runs);
        // Each run gets exactly ε / R: less would price every run dearer than the union bound needs.
        Assert.Equal(frame / runs, budget.PerRun, frame / runs * 1e-12);
        // Union bound: R runs each failing with probability at most ε / R fail together with at most ε,
        // and even independent failures, 1 − (1 − ε/R)^R, stay below it.
        Assert.True(budget.PerRun * runs <= frame * (1 + 1e-12));
        Assert.True(-double.ExpM1(runs * double.LogP1(-budget.PerRun)) <= frame * (1 + 1e-12));
    }

    [Theory]
    [InlineData(0.0)]
    [InlineData(1.0)]
    [InlineData(-0.1)]
    [InlineData(1.5)]
    [InlineData(double.NaN)]
    public void BudgetsOutsideZeroToOneAreRefused(double budget) => Assert.NotNull(FrameBudget.Problem(budget));

    [Fact]
    public void MakespanOnOneProcessorIsTheSumAndOnManyTheLongestJob()
    {
        double[] jobs = [3, 1, 4, 1, 5, 9, 2, 6];
        Assert.Equal(jobs.Sum(), FrameCost.Makespan(jobs, 1));
        Assert.Equal(9, FrameCost.Makespan(jobs, jobs.Length));
        Assert.Equal(9, FrameCost.Makespan(jobs, 100));
        // Longest first onto the least loaded of 3, by hand: 9 → A (9), 6 → B (6), 5 → C (5), 4 → C (9), 3 → B (9);
        // then all three hold 9: 2 → one (11), 1 and 1 → the other two (10 each).
        Assert.Equal(11, FrameCost.Makespan(jobs, 3));
        // Never below the average load nor the longest job.
        Assert.True(FrameCost.Makespan(jobs, 3) >= jobs.Sum() / 3);
    }
}
