using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Engines;
using QuantumRayTracing.Tests.Statistics;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Rendering;

/// <summary>
/// The primary pass on the Q# full-state engine against the analytic engine: the same per-ray outcome
/// distribution. Full-state measurements cannot be seeded, so the comparison is a chi-square
/// homogeneity test at false-failure <see cref="StatisticalBounds.FalseFailure"/>.
/// </summary>
[Collection(QSharpCollection.Name)]
public class FullStateRenderTests(FullStateFixture fixture)
{
    private static readonly Scene Qornell8 = Load("qornell-8.json");

    /// <summary>The shared engine, lent to a search without handing over its bridges.</summary>
    private sealed class Borrowed(IGroverEngine engine) : IGroverEngine
    {
        public string Name => engine.Name;
        public IReadOnlyList<int> Measure(IReadOnlyList<GroverRequest> requests) => engine.Measure(requests);
        public void Dispose() { }
    }

    private enum Outcome { Closest, Other, Nothing }

    /// <summary>Per-ray outcome counts of <paramref name="repeats"/> one-round primary passes at 12x12.</summary>
    private static int[] Outcomes(Func<int, IHitSearch> search, int repeats)
    {
        var geometry = new SceneGeometry(Qornell8);
        var rays = CameraRays.For(Qornell8.Camera, 12, 12);
        using var classical = new ClassicalHitSearch();
        var (reference, _) = TracePass.Run("primary", classical, geometry, rays, new PassOptions(1, TieBreak.Strict));
        var outcomes = new List<int>();
        for (var k = 0; k < repeats; k++)
        {
            using var engine = search(k);
            var (hits, _) = TracePass.Run("primary", engine, geometry, rays, new PassOptions(1, TieBreak.Strict));
            for (var i = 0; i < rays.Length; i++)
                outcomes.Add((int)(hits[i] is not { } h ? Outcome.Nothing : h.Primitive == reference[i]?.Primitive ? Outcome.Closest : Outcome.Other));
        }
        return StatisticalBounds.Histogram(outcomes, 3);
    }

    [Fact]
    public void PrimaryPassOutcomesMatchTheAnalyticEngine()
    {
        // Each ray's outcome has the same distribution on both engines if they agree, so pooled over the
        // same rays the two histograms are samples of one distribution. Rays differ in their number of hits,
        // which makes the pooled counts less variable than multinomial: the test is conservative.
        var fullState = Outcomes(_ => new QuantumHitSearch(new Borrowed(fixture.Engine), new SeededRandom(77), new QSearchOptions()), 6);
        var analytic = Outcomes(k => new QuantumHitSearch(new AnalyticEngine(new SeededRandom(200 + (ulong)k)), new SeededRandom(300 + (ulong)k), new QSearchOptions()), 30);
        Assert.All(new[] { fullState, analytic }, h => Assert.All(h, count => Assert.True(count > 0, "every outcome should occur")));
        StatisticalBounds.AssertSameDistribution(fullState, analytic, "primary pass outcomes (closest, other, nothing), fullstate vs analytic");
    }
}
