using QuantumRayTracing.Engines;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Tests.Passes;

/// <summary>
/// The cheap confirmation sized per lattice level (<see cref="CheapConfirmation"/>) at N = 4,096 on the analytic engine,
/// beside the fixed list missing at most 40 % (39 queries and tests per empty search).
/// </summary>
public sealed class CheapConfirmationTests
{
    private const int N = 4096;

    // The per-ray share of a 64x64 primary pass's allowance: half of 0.1 % of the pixels over its 4,096 rays.
    private const double Share = 0.0005;

    private static readonly QSearchSchedule Fixed = ConfirmationPlanner.Cheapest(N, ConfirmationPlanner.MaxT, 0.4)!;

    private static QuantumHitSearch Search() => new(new AnalyticEngine(new SeededRandom(1)), new SeededRandom(2), new QSearchOptions());

    [Fact]
    public void WithoutAnAllowanceEveryLevelTakesTheFixedList()
    {
        using var search = Search();
        Assert.Same(Fixed, new CheapConfirmation(Fixed, sized: false, search, N, full: null).For(3072, Share));
        Assert.Same(Fixed, new CheapConfirmation(Fixed, sized: true, search, N, full: null).For(3072, share: null));
    }

    /// <summary>
    /// A level of 3,072 agreeing rays (level 0 at 64x64) that finds nothing is charged about ½ w / (1 − w) by the ledger,
    /// within its share (1.5) for w up to 0.75: it takes a list weaker and cheaper than the fixed one. A level of 24 rays is
    /// charged as much for far fewer rays, 24 times its share at w = 0.5: it takes a list stronger than the fixed one.
    /// </summary>
    [Fact]
    public void ALevelOfManyRaysTakesAWeakerListThanALevelOfFew()
    {
        using var search = Search();
        var sized = new CheapConfirmation(Fixed, sized: true, search, N, full: null);
        var (many, few) = (sized.For(3072, Share), sized.For(24, Share));
        double Miss(QSearchSchedule s) => ConfirmationPlanner.WorstMiss(search, N, s);
        Assert.True(Miss(many) > 0.4, $"3,072 rays: {many}, miss {Miss(many):0.000}");
        Assert.True(search.EmptySearchCost(N, many) < search.EmptySearchCost(N, Fixed), $"3,072 rays: {many} costs as much as {Fixed}");
        Assert.True(Miss(few) < 0.4, $"24 rays: {few}, miss {Miss(few):0.000}");
        Assert.True(sized.Contains(many) && sized.Contains(few) && sized.Contains(Fixed));
        Assert.False(sized.Contains(ConfirmationPlanner.Cheapest(N, ConfirmationPlanner.MaxT, 0.4)), "a round's own list is not the cheap path's");
    }
}
