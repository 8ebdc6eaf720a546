using QuantumRayTracing.Engines;
using QuantumRayTracing.Output;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Statistics;

namespace QuantumRayTracing.Tests.Search;

/// <summary><see cref="SearchRun"/> called as a library, on the analytic engine: its figures, its seed and its miss rate.</summary>
public sealed class SearchRunTests
{
    private static SearchRunSettings Settings(IReadOnlyList<int>? marked, int searches, ulong seed) =>
        new(64, marked, searches, new EngineSetup(EngineKind.Analytic), seed);

    [Fact]
    public void MissesAsOftenAsQSearchsExactRate()
    {
        const int searches = 4000;
        var run = SearchRun.Run(Settings([17], searches, 3));
        var miss = FalseNegativeRate.QSearchExact(new QSearchSchedule(64, QSearchSchedule.DefaultGrowth, MSetRule.Ceiling), 1);

        StatisticalBounds.AssertBinomial(run.Figures.NotFound, miss, searches, "searches that missed the one marked index of 64");
        Assert.Equal(searches, run.Figures.Found + run.Figures.NotFound);
        Assert.Equal([17], run.Figures.Marked);
        Assert.Equal(RunPlace.NoBridges, run.RanOn);
    }

    [Theory]
    [InlineData(new[] { 3, 17 }, null)]
    [InlineData(new int[0], null)]
    [InlineData(new[] { 2, 64, -1 }, "--marked: index 64 is outside 0..63")]
    [InlineData(new[] { -1 }, "--marked: index -1 is outside 0..63")]
    [InlineData(new[] { 5, 9, 5 }, "--marked: an index is listed twice")]
    public void MarkedIndicesMustBeDistinctAndBelowN(int[] marked, string? problem) =>
        Assert.Equal(problem, SearchRunSettings.MarkedProblem(64, marked));

    [Theory]
    [InlineData(new[] { "-m", "70" }, "--marked: index 70 is outside 0..63")]
    [InlineData(new[] { "-n", "16", "-m", "16" }, "--marked: index 16 is outside 0..15")]
    public void TheCommandChecksMarkedIndicesAgainstN(string[] options, string problem)
    {
        // Without -n the rule checks against the default N = 64, not against 0.
        var (code, error) = QuantumRayTracing.Tests.Cli.ConsoleCapture.Run(["search", "-e", "analytic", "-s", "1", .. options]);
        Assert.Equal(1, code);
        Assert.Contains(problem, error);
        Assert.Equal(0, QuantumRayTracing.Tests.Cli.ConsoleCapture.Run(["search", "-e", "analytic", "-s", "1", "-m", "63"]).Code);
    }

    [Fact]
    public void NoMarkedIndexIsNeverFound()
    {
        var run = SearchRun.Run(Settings([], 50, 3));
        Assert.Equal(0, run.Figures.Found);
        Assert.True(run.Figures.Rounds > 1, "searches over nothing run through their whole schedule");
    }

    [Fact]
    public void TheSeedFixesTheDrawnIndexAndTheFigures()
    {
        var first = SearchRun.Run(Settings(null, 200, 7));
        var again = SearchRun.Run(Settings(null, 200, 7));
        Assert.Single(first.Figures.Marked);
        Assert.InRange(first.Figures.Marked[0], 0, 63);
        Assert.Equal(first.Figures.Marked, again.Figures.Marked);
        Assert.Equal((first.Figures.Found, first.Figures.Total, first.Figures.Rounds), (again.Figures.Found, again.Figures.Total, again.Figures.Rounds));

        var drawn = Enumerable.Range(1, 20).Select(seed => Settings(null, 1, (ulong)seed).MarkedSet.Indices.ToArray()[0]).Distinct().Count();
        Assert.True(drawn > 1, "twenty seeds drew one index: the draw ignores the seed");
    }
}
