using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Statistics;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Search;

/// <summary>
/// The pooled search (<see cref="IPooledSearch"/>) on rays whose accepted rows are known by construction: one ray from
/// (3.5, 3.5, 0) along +z meets rectangles 0..3 at depths 10, 4, 8 and 8 and misses 4 and 5; a window beyond depth 11
/// accepts none of them, a window from 9 to 15 accepts rectangle 0 alone.
/// </summary>
public class PooledSearchTests
{
    private static readonly RayTable Stack = Table(With(4, 0,
        Rect(0, 0, 10, 8, 8, 10), Rect(0, 0, 4, 8, 8, 4), Rect(0, 0, 8, 8, 8, 8), Rect(0, 0, 8, 8, 8, 8), Rect(10, 10, 2, 12, 12, 2), Rect(10, 10, 9, 12, 12, 9)),
        new Ray(new Vec3(3.5, 3.5, 0), new Vec3(0, 0, 1)));

    private static readonly HitWindow Nothing = new(11, 15, 6), OnlyFirst = new(9, 15, 6);

    private static QuantumHitSearch Pooling(ulong seed) =>
        new(new AnalyticEngine(new SeededRandom(seed).Fork(RandomStreams.Engine)), new SeededRandom(seed).Fork(RandomStreams.Search), new QSearchOptions(), pooled: true);

    /// <summary>
    /// 256 rays, one of them wrong by one pair among 1,536: 3,000 pooled searches find exactly that pair (ray 97, rectangle 0)
    /// or nothing, and miss at QSearch's exact rate for t = 1 over the pool's 1,536 pairs (binomial check, false-failure
    /// 1e-8). The rate of a pool of half or twice the size (0.125 and 0.171 against 0.089: misses are not monotone in the pool size) lies outside the acceptance:
    /// the check would catch a search over the wrong number of pairs.
    /// </summary>
    [Fact]
    public void PooledSearchFindsTheWrongRaysPairAtQSearchsRateOverThePool()
    {
        const int rays = 256, wrongRay = 97, trials = 3000;
        using var search = Pooling(11);
        HitQuery[] queries = [.. Enumerable.Range(0, rays).Select(k => new HitQuery(Stack, k == wrongRay ? OnlyFirst : Nothing))];
        var misses = 0;
        for (var trial = 0; trial < trials; trial++)
        {
            var outcome = search.RunPooled(queries);
            if (outcome.Query is null) misses++;
            else Assert.Equal((wrongRay, 0), (outcome.Query.Value, outcome.Primitive!.Value));
        }
        var rate = FalseNegativeRate.QSearchExact(search.PooledSchedule(rays, Stack.Count), 1);
        StatisticalBounds.AssertBinomial(misses, rate, trials, "pooled misses");
        var (low, high) = StatisticalBounds.BinomialInterval(rate, trials);
        foreach (var other in new[] { rays / 2, rays * 2 })
        {
            var wrong = FalseNegativeRate.QSearchExact(search.PooledSchedule(other, Stack.Count), 1) * trials;
            Assert.True(wrong < low || wrong > high, $"a pool of {other} rays ({wrong:0} misses expected) passes the check");
        }
    }

    /// <summary>A pool with nothing accepted finds nothing and costs a whole empty search: every run and its test.</summary>
    [Fact]
    public void AnEmptyPoolFindsNothing()
    {
        using var search = Pooling(3);
        var outcome = search.RunPooled([.. Enumerable.Repeat(new HitQuery(Stack, Nothing), 40)]);
        Assert.Null(outcome.Query);
        Assert.Equal(search.PooledSchedule(40, Stack.Count).Bounds.Count + 1, outcome.Cost.GroverRuns);
    }

    /// <summary>
    /// The ledger lowers a pooled ray's odds by the pooled schedule's worst miss for t ≤ 8 marked pairs, while the pool may
    /// hold more (other wrong rays' pairs): that is safe because QSearch misses less often as more pairs are marked. Checked
    /// from 9 to 512 marked pairs, on pools of the sizes renders use.
    /// </summary>
    [Theory]
    [InlineData(6 * 256)]
    [InlineData(64 * 100)]
    [InlineData(64 * 16384)]
    [InlineData(4096 * 2600)]
    public void MorePairsMarkedMissLessOften(int pairs)
    {
        var schedule = new QSearchSchedule(pairs);
        var worst = Enumerable.Range(1, 8).Max(t => FalseNegativeRate.QSearchExact(schedule, t));
        foreach (var t in new[] { 9, 12, 16, 24, 32, 48, 64, 128, 256, 512 }.Where(t => t < pairs / 4))
            Assert.True(FalseNegativeRate.QSearchExact(schedule, t) <= worst, $"{pairs} pairs, t = {t}: miss above the worst for t ≤ 8 ({worst:0.0000})");
    }

    /// <summary>Only the noiseless analytic engine pools rays; others refuse a pooled search.</summary>
    [Fact]
    public void OnlyTheNoiselessAnalyticEnginePools()
    {
        var options = new QSearchOptions();
        using var analytic = EngineFactory.CreateSearch(EngineKind.Analytic, new SeededRandom(1), 1, options);
        using var noisy = EngineFactory.CreateSearch(EngineKind.Analytic, new SeededRandom(1), 1, options, noise: NoiseModel.Depolarizing(1e-4));
        using var classical = EngineFactory.CreateSearch(EngineKind.Classical, new SeededRandom(1), 1, options);
        Assert.True(analytic is IPooledSearch { PoolsRays: true });
        Assert.False(noisy is IPooledSearch { PoolsRays: true });
        Assert.False(classical is IPooledSearch);
        Assert.Throws<InvalidOperationException>(() => ((IPooledSearch)noisy).RunPooled([new HitQuery(Stack, OnlyFirst)]));
    }

    /// <summary>A round's rays are split into pools of at most 2^30 pairs that together hold every ray.</summary>
    [Theory]
    [InlineData(64, 67_108_864)]
    [InlineData(4096, 1_000_000)]
    [InlineData(6, 256)]
    public void PoolsHoldEveryRayAndAtMostTheMostPairs(int count, int rays)
    {
        var pools = QuantumRayTracing.Passes.PooledRound.Pools(rays, count).ToArray();
        Assert.Equal(rays, pools.Sum());
        Assert.All(pools, size => Assert.InRange((long)size * count, 1, IPooledSearch.MaxPairs));
        Assert.Equal((int)Math.Ceiling((double)rays * count / IPooledSearch.MaxPairs), pools.Length);
    }
}
