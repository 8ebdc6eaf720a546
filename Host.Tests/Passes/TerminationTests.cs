using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Statistics;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Passes;

/// <summary>The sec. 6.2 termination criterion: its draws, and the false-negative rate it leaves.</summary>
public sealed class TerminationTests
{
    [Fact]
    public void ContinuesWithProbabilityMissToThePowerOfConsecutiveMisses()
    {
        const int draws = 40_000;
        var rule = new StopRule(0.3, new SeededRandom(9));
        Assert.True(Enumerable.Range(0, 100).All(_ => rule.Continue(0)));
        StatisticalBounds.AssertBinomial(Enumerable.Range(0, draws).Count(_ => rule.Continue(1)), 0.3, draws, "continue after 1 miss");
        StatisticalBounds.AssertBinomial(Enumerable.Range(0, draws).Count(_ => rule.Continue(2)), 0.09, draws, "continue after 2 misses");
    }

    [Fact]
    public void ObservedFalseNegativeRateMatchesItsEstimate()
    {
        // Shadow rays that each cross exactly one occluder among N = 16 planes (t = 1). A ray ends
        // unoccluded only if its searches miss until the stop rule ends it: with per-search miss q and
        // stop parameter p, P = Σ_k q^k · ∏_{j<k} p^j · (1 − p^k), for k up to the round limit (then 1).
        var planes = Enumerable.Range(0, 16).Select(k => k == 5 ? Rect(0, 0, 6, 15, 15, 6) : Rect(20, 20, 1 + k % 3, 21, 21, 1 + k % 3)).ToArray();
        var geometry = new SceneGeometry(With(5, 0, planes));
        var ray = new Ray(new Vec3(7.5, 7.5, 0.5), new Vec3(0, 0, 10), MaxDistance: 1);
        const int rays = 20_000, rounds = 6;
        const double p = 0.25;
        var schedule = new QSearchSchedule(16);
        var q = FalseNegativeRate.QSearchExact(schedule, 1);
        double expected = 0, reach = 1; // reach: probability of being searched a k-th time after k − 1 misses
        for (var k = 1; k <= rounds; k++)
        {
            var missAll = Math.Pow(q, k);
            var stopHere = k == rounds ? 1 : 1 - Math.Pow(p, k);
            expected += missAll * reach * stopHere;
            reach *= Math.Pow(p, k);
        }
        var random = new SeededRandom(23);
        using var search = new QuantumHitSearch(new AnalyticEngine(random.Fork(RandomStreams.Engine)), random.Fork(RandomStreams.Search), new QSearchOptions());
        var (occluded, _) = DirectPass.Run("shadow", search, geometry, Enumerable.Repeat(ray, rays).ToArray(),
            new PassOptions(rounds, Stop: new StopRule(p, random.Fork(RandomStreams.Stop))));
        StatisticalBounds.AssertBinomial(occluded.Count(o => !o), expected, rays, "rays ended unoccluded");
    }
}
