using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Search;
using QuantumRayTracing.Tests.Statistics;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Passes;

/// <summary>DirectPass (Algorithm 6): shadow rays on a scene where each ray's blockers are known by hand.</summary>
public class DirectPassTests
{
    // id 0: the floor y = 0 the rays leave from (excluded); id 1: a blocker at y = 2 over x 5..6, z 3..5;
    // id 2: a ceiling y = 6 beyond the light (t = 1.5); id 3: a wall x = 0 behind both origins (t < 0);
    // id 4: a plane y = 4 through the light itself (t = 1, where the segment ends: not a blocker).
    private static readonly SceneGeometry Geometry = new(With(4, 0,
        Rect(0, 0, 0, 8, 0, 8), Rect(5, 2, 3, 6, 2, 5), Rect(0, 6, 0, 15, 6, 8), Rect(0, 0, 0, 0, 8, 8), Rect(0, 4, 0, 8, 4, 8)));

    private static readonly Vec3 Light = new(7, 4, 4);

    // From (4, 0, 4): at y = 2 (t = 0.5) the segment is at (5.5, 2, 4), inside the blocker.
    private static readonly Ray Occluded = new(new Vec3(4, 0, 4), Light - new Vec3(4, 0, 4), MaxDistance: 1, ExcludedPrimitive: 0);

    // From (1, 0, 1): at y = 2 (t = 0.5) the segment is at (4, 2, 2.5), beside the blocker.
    private static readonly Ray Visible = new(new Vec3(1, 0, 1), Light - new Vec3(1, 0, 1), MaxDistance: 1, ExcludedPrimitive: 0);

    private static QuantumHitSearch Quantum(ulong seed) =>
        new(new AnalyticEngine(new SeededRandom(seed).Fork(RandomStreams.Engine)), new SeededRandom(seed).Fork(RandomStreams.Search), new QSearchOptions());

    [Fact]
    public void RowsAreAsDescribed()
    {
        var occluded = RayTable.Build(Geometry, Occluded);
        Assert.Equal([1], occluded.Marked(occluded.FullRange).Indices.ToArray());
        var visible = RayTable.Build(Geometry, Visible);
        Assert.Empty(visible.Marked(visible.FullRange).Indices.ToArray());
        // Without the segment's end the plane through the light and the ceiling would block it.
        var unbounded = RayTable.Build(Geometry, Visible with { MaxDistance = double.PositiveInfinity });
        Assert.Equal([2, 4], unbounded.Marked(unbounded.FullRange).Indices.ToArray());
    }

    [Fact]
    public void ClassicalReportsExactlyTheOccludedRayInOneRound()
    {
        using var search = new ClassicalHitSearch();
        var (occluded, metrics) = DirectPass.Run("shadow", search, Geometry, [Occluded, Visible, Occluded], new PassOptions(DirectPass.DefaultIterations));
        Assert.Equal([true, false, true], occluded);
        Assert.Equal(1, metrics.Iterations);
        Assert.Equal(new SearchCost(0, 0, 3 * 5, 0), metrics.Cost);
    }

    [Fact]
    public void NoEngineReportsAVisibleLightOccluded()
    {
        var rays = Enumerable.Repeat(Visible, 500).ToArray();
        for (var seed = 1UL; seed <= 4; seed++)
        {
            using var quantum = Quantum(seed);
            Assert.DoesNotContain(true, DirectPass.Run("shadow", quantum, Geometry, rays, new PassOptions(4)).Occluded);
            using var randomized = new RandomizedHitSearch(new SeededRandom(seed));
            Assert.DoesNotContain(true, DirectPass.Run("shadow", randomized, Geometry, rays, new PassOptions(4)).Occluded);
        }
    }

    [Fact]
    public void QuantumMissesAnOccluderAtTheFalseNegativeRateOfEachRound()
    {
        // One blocker of N = 5: a round misses with QSearch's false-negative probability q; a ray still
        // unoccluded after two rounds missed twice: q².
        const int rays = 5000;
        using var quantum = Quantum(8);
        var (occluded, metrics) = DirectPass.Run("shadow", quantum, Geometry, Enumerable.Repeat(Occluded, rays).ToArray(), new PassOptions(2));
        var q = QSearchExpectations.FalseNegative(5, 1, new QSearchSchedule(5));
        StatisticalBounds.AssertBinomial(occluded.Count(o => !o), q * q, rays, "shadow rays left unoccluded after 2 rounds");
        Assert.Equal(2, metrics.Iterations);
    }

    [Fact]
    public void RandomizedFindsAnOccluderWithItsSampleRate()
    {
        // k = floor(sqrt 5) = 2 distinct rows of 5 per round, one of them the blocker: found with 2/5 per round,
        // still unoccluded after two rounds with (3/5)².
        const int rays = 5000;
        using var randomized = new RandomizedHitSearch(new SeededRandom(9));
        var (occluded, _) = DirectPass.Run("shadow", randomized, Geometry, Enumerable.Repeat(Occluded, rays).ToArray(), new PassOptions(2));
        StatisticalBounds.AssertBinomial(occluded.Count(o => !o), 0.36, rays, "randomized shadow rays left unoccluded");
    }
}
