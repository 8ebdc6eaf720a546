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

/// <summary>TracePass (Algorithm 4) on the classical reference and on QSearch over the analytic engine.</summary>
public class TracePassTests
{
    private static readonly Scene Qornell8 = Load("qornell-8.json");
    private static readonly Scene Qornell16 = Load("qornell-16.json");

    private static QuantumHitSearch Quantum(ulong seed) =>
        new(new AnalyticEngine(new SeededRandom(seed).Fork(RandomStreams.Engine)), new SeededRandom(seed).Fork(RandomStreams.Search), new QSearchOptions());

    private static (Hit?[] Hits, PassMetrics Metrics) Trace(Scene scene, IHitSearch search, int size, int iterations, TieBreak tieBreak = TieBreak.Strict) =>
        TracePass.Run("primary", search, new SceneGeometry(scene), CameraRays.For(scene.Camera, size, size), new PassOptions(iterations, tieBreak));

    [Fact]
    public void CentreRayOfQornellHitsTheBackWall()
    {
        // A 1x1 image's ray is the view direction: from (8, 8, 2) along +z to the back wall z = 30
        // (id 2) at (8, 8, 30), depth 30 − 2 = 28; the block spans x 9..13, so it is not in the way.
        using var search = new ClassicalHitSearch();
        var (hits, _) = Trace(Qornell8, search, 1, 4);
        var hit = Assert.Single(hits)!.Value;
        Assert.Equal(2, hit.Primitive);
        Assert.Equal(28, hit.Depth);
        Assert.Equal(28, hit.Distance, 9);
        Assert.Equal(8, hit.Point.X, 9);
        Assert.Equal(8, hit.Point.Y, 9);
        Assert.Equal(30, hit.Point.Z, 9);
    }

    [Fact]
    public void ClassicalFinishesInOneRoundAtNTestsPerRay()
    {
        using var search = new ClassicalHitSearch();
        var (_, metrics) = Trace(Qornell16, search, 16, 4);
        Assert.Equal(1, metrics.Iterations);
        Assert.Equal(256, metrics.Rays);
        Assert.Equal(new SearchCost(0, 0, 256 * 16, 0), metrics.Cost); // N = 16 tests for each of 16 · 16 rays
        Assert.Equal(256 * 16, metrics.TableRows);
        Assert.Equal(16.0, metrics.PerRayConservative);
    }

    [Theory]
    [InlineData("qornell-16.json", 32)]
    [InlineData("depth-complexity-32.json", 24)]
    public void ClassicalHitsAreTheBruteForceClosest(string file, int size)
    {
        var scene = Load(file);
        var geometry = new SceneGeometry(scene);
        var rays = CameraRays.For(scene.Camera, size, size);
        using var search = new ClassicalHitSearch();
        var (hits, _) = TracePass.Run("primary", search, geometry, rays, new PassOptions(1, TieBreak.Strict));
        for (var i = 0; i < rays.Length; i++)
        {
            var table = RayTable.Build(geometry, rays[i]);
            var expected = BruteForceClosest(table);
            Assert.Equal(expected, hits[i]?.Primitive);
            if (expected is { } p) Assert.Equal((table.Depth(p), table.Distance(p)), (hits[i]!.Value.Depth, hits[i]!.Value.Distance));
        }
        // Not vacuous: the image shows several primitives.
        Assert.True(hits.Where(h => h is not null).Select(h => h!.Value.Primitive).Distinct().Count() >= 5);
    }

    [Fact]
    public void QuantumHitIsNeverCloserThanTheClassicalOne()
    {
        var geometry = new SceneGeometry(Qornell16);
        var rays = CameraRays.For(Qornell16.Camera, 32, 32);
        using var classical = new ClassicalHitSearch();
        var (reference, _) = TracePass.Run("primary", classical, geometry, rays, new PassOptions(1, TieBreak.Strict));
        foreach (var (seed, iterations) in new[] { (1UL, 1), (2UL, 2), (3UL, 4) })
        {
            using var quantum = Quantum(seed);
            var (hits, metrics) = TracePass.Run("primary", quantum, geometry, rays, new PassOptions(iterations, TieBreak.Strict));
            Assert.Equal(iterations, metrics.Iterations); // never certain, so every round runs
            var farther = 0;
            for (var i = 0; i < rays.Length; i++)
            {
                if (hits[i] is not { } q) continue;
                Assert.True(reference[i] is not null, $"pixel {i}: quantum hit {q.Primitive} where classical has none");
                var c = reference[i]!.Value;
                // The classical hit is the (depth, id) minimum of the accepted rows, so anything else is behind it.
                Assert.True(q.Depth > c.Depth || (q.Depth == c.Depth && q.Primitive >= c.Primitive),
                    $"pixel {i}: quantum (depth {q.Depth}, id {q.Primitive}) is before classical (depth {c.Depth}, id {c.Primitive})");
                var table = RayTable.Build(geometry, rays[i]);
                Assert.True(table.Verify(q.Primitive, table.FullRange), $"pixel {i}: quantum hit {q.Primitive} is not on the ray");
                if (q.Primitive != c.Primitive) farther++;
            }
            // One pass leaves some hits behind the closest (the check above was exercised).
            if (iterations == 1) Assert.True(farther > 0);
        }
    }

    [Fact]
    public void WrongPixelsFollowTheFalseNegativeRateAndFallWithPasses()
    {
        // A pixel ends on a hit other than the classical one with the probability of PassExpectations.WrongAfter,
        // given its number of accepted rows; pixels are independent, so the count of wrong pixels is
        // Poisson-binomial. Each count must fall in its exact interval at false-failure 1e-8.
        var geometry = new SceneGeometry(Qornell16);
        var rays = CameraRays.For(Qornell16.Camera, 32, 32);
        using var classical = new ClassicalHitSearch();
        var (reference, _) = TracePass.Run("primary", classical, geometry, rays, new PassOptions(1, TieBreak.Strict));
        var accepted = rays.Select(r => { var t = RayTable.Build(geometry, r); return t.Marked(t.FullRange).MarkedCount; }).ToArray();
        Assert.True(accepted.Max() >= 3, "the scene should have rays with several hits");
        var schedule = new QSearchSchedule(geometry.Count);
        var intervals = new Dictionary<int, (int Low, int High)>();
        foreach (var iterations in new[] { 1, 8 })
        {
            var probabilities = accepted.Select(t => PassExpectations.WrongAfter(geometry.Count, t, iterations, schedule)).ToArray();
            var interval = PassExpectations.PoissonBinomialInterval(probabilities, StatisticalBounds.FalseFailure);
            intervals[iterations] = interval;
            using var quantum = Quantum(100 + (ulong)iterations);
            var (hits, _) = TracePass.Run("primary", quantum, geometry, rays, new PassOptions(iterations, TieBreak.Strict));
            var wrong = Enumerable.Range(0, rays.Length).Count(i => hits[i]?.Primitive != reference[i]?.Primitive);
            Assert.True(wrong >= interval.Low && wrong <= interval.High,
                $"#IT = {iterations}: {wrong} of {rays.Length} pixels differ from classical; expected {probabilities.Sum():0.#}, interval [{interval.Low}, {interval.High}]");
        }
        // The two intervals are disjoint, so the check above also shows that more passes leave fewer wrong pixels;
        // at #IT = 8 the bound stays under 2% of the 1024 pixels.
        Assert.True(intervals[8].High < intervals[1].Low, $"intervals {intervals[8]} and {intervals[1]} overlap");
        Assert.True(intervals[8].High <= 20, $"#IT = 8 upper bound {intervals[8].High}");
    }

    // Ids 1 and 2 are hit at the same depth 8, id 0 behind them at 12; id 3 is missed (N = 4).
    private static readonly Scene Tie = With(4, 0,
        Rect(0, 0, 12, 8, 8, 12), Rect(0, 0, 8, 8, 8, 8), Rect(2, 2, 8, 6, 6, 8), Rect(10, 10, 4, 12, 12, 4));

    private static readonly Ray[] TieRay = [new(new Vec3(3.5, 3.5, 0), new Vec3(0, 0, 1))];

    [Fact]
    public void StrictTiesGoToTheSmallerIdRandomTiesVaryAcrossSeeds()
    {
        // Reaching id 1 under strict takes at most 3 finds (0 → 2 → 1 at worst). A round with t marked of N = 4
        // misses with probability at most 0.28125 (t = 1: (3/4) · (1 − (sin²(π/2) + sin²(5π/6)) / 2)), so
        // P(fewer than 3 finds in 24 rounds) ≤ 1.2e-10 per seed; the seeds are fixed, so the outcome is too.
        const int seeds = 300, rounds = 24;
        var geometry = new SceneGeometry(Tie);
        var strict = new int?[seeds];
        var random = new int?[seeds];
        for (var s = 0; s < seeds; s++)
        {
            using (var search = Quantum((ulong)s)) strict[s] = TracePass.Run("primary", search, geometry, TieRay, new PassOptions(rounds, TieBreak.Strict)).Hits[0]?.Primitive;
            using (var search = Quantum((ulong)s)) random[s] = TracePass.Run("primary", search, geometry, TieRay, new PassOptions(rounds, TieBreak.Random)).Hits[0]?.Primitive;
        }
        Assert.All(strict, p => Assert.Equal(1, p));
        // Random keeps whichever depth-8 primitive it lands on first; ids 1 and 2 are symmetric, so each is
        // chosen with probability 1/2 among the seeds that end at depth 8 (all of them, up to the bound above).
        Assert.All(random, p => Assert.Contains(p, new int?[] { 1, 2 }));
        StatisticalBounds.AssertBinomial(random.Count(p => p == 2), 0.5, seeds, "random tie-break: id 2 chosen");
        using var classical = new ClassicalHitSearch();
        Assert.Equal(1, TracePass.Run("primary", classical, geometry, TieRay, new PassOptions(1, TieBreak.Random)).Hits[0]?.Primitive);
    }

    [Fact]
    public void APassLeftNoAllowanceByEarlierPassesEndsWithoutRounds()
    {
        // A primary pass that ends over its allowance leaves the later passes less than nothing (the render now gives them
        // none); a pass with no rays (a scene without mirrors has no specular rays) must then end at once instead of looking
        // for the likeliest wrong ray among none.
        var search = Quantum(1);
        var (hits, metrics) = TracePass.Run("specular", search, new SceneGeometry(Qornell8), [], new PassOptions(1, Allowance: -1));
        Assert.Empty(hits);
        Assert.Equal(0, metrics.ExpectedWrong);
        Assert.Equal(0, metrics.RoundIntersections);
    }
}
