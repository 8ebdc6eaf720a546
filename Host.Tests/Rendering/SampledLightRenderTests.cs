using QuantumRayTracing.Cli;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Output;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using QuantumRayTracing.Shading;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Rendering;

/// <summary>
/// Area lights and VPLs through the whole renderer: byte-identical per seed, the classical engine's
/// cost and convergence to the many-sample reference, and what the optimisations may and may not change.
/// </summary>
public class SampledLightRenderTests
{
    private static readonly Scene Area = Load("qornell-64-area.json");
    private static readonly Scene Temple = Load("temple-32.json");

    private static RenderResult Render(Scene scene, EngineKind kind, ulong seed, RenderOptions options)
    {
        using var search = EngineFactory.CreateSearch(kind, new SeededRandom(seed), 1, new QSearchOptions());
        return SceneRenderer.Render(scene, search, options with { Seed = seed });
    }

    private static byte[] Png(Scene scene, EngineKind kind, ulong seed, RenderOptions options) =>
        PngWriter.Encode(Render(scene, kind, seed, options).Image);

    // RMS over pixels and channels of the linear radiance difference.
    private static double Error(RenderResult a, RenderResult b) =>
        Math.Sqrt(a.Radiance.Zip(b.Radiance).Average(p => (p.First - p.Second).Dot(p.First - p.Second) / 3));

    private static readonly RenderOptions AreaOptions = new(12, 12, AreaSamples: 4);
    private static readonly RenderOptions TempleOptions = new(12, 12, Vpl: 2);

    public static TheoryData<EngineKind> SeededEngines => [EngineKind.Analytic, EngineKind.Classical, EngineKind.Randomized];

    [Theory]
    [MemberData(nameof(SeededEngines))]
    public void SameSeedGivesTheSameBytes(EngineKind kind)
    {
        Assert.Equal(Png(Area, kind, 3, AreaOptions), Png(Area, kind, 3, AreaOptions));
        Assert.Equal(Png(Temple, kind, 3, TempleOptions), Png(Temple, kind, 3, TempleOptions));
    }

    [Theory]
    [MemberData(nameof(SeededEngines))]
    public void AnotherSeedMovesTheSamples(EngineKind kind)
    {
        // Even the classical engine, whose searches are certain, samples the light elsewhere.
        Assert.NotEqual(Png(Area, kind, 3, AreaOptions), Png(Area, kind, 4, AreaOptions));
        Assert.NotEqual(Png(Temple, kind, 3, TempleOptions), Png(Temple, kind, 4, TempleOptions));
    }

    [Fact]
    public void ClassicalPassesCostNTestsPerRay()
    {
        var area = Render(Area, EngineKind.Classical, 1, AreaOptions);
        Assert.Equal(["primary", "specular", "shadow", AreaLightPass.Name], area.Passes.Select(p => p.Name));
        Assert.Equal(0, area.Passes[2].Rays); // no point or directional light
        Assert.True(area.Passes[3].Rays > 4 * 12 * 12 / 2, "most points see the light with all 4 samples");
        Assert.All(area.Passes.Where(p => p.Rays > 0), p => Assert.Equal(64.0, p.PerRayConservative));

        var temple = Render(Temple, EngineKind.Classical, 1, TempleOptions);
        Assert.Equal(["primary", "specular", "shadow", IndirectPass.TraceName, IndirectPass.ShadowName], temple.Passes.Select(p => p.Name));
        // Every surface point sends its 2 VPL rays; no mirror, so the points are the primary hits.
        Assert.Equal(2 * PrimaryHits(Temple, 12), temple.Passes[3].Rays);
        Assert.All(temple.Passes.Where(p => p.Rays > 0), p => Assert.Equal(32.0, p.PerRayConservative));
        Assert.Equal(temple.Passes.Sum(p => p.Rays), temple.Total.Rays);
    }

    private static int PrimaryHits(Scene scene, int size)
    {
        var geometry = new SceneGeometry(scene);
        return CameraRays.For(scene.Camera, size, size).Count(r => BruteForceClosest(RayTable.Build(geometry, r)) is not null);
    }

    [Fact]
    public void ClassicalAreaLightConvergesToTheManySampleReference()
    {
        // Stratified samples: each 4x more samples should cut the RMS error about 2x (plain Monte Carlo) or
        // better; required: at least 1.5x per step, and 64 samples at least 10x better than 1. Fixed seed.
        var reference = Render(Area, EngineKind.Classical, 1, new RenderOptions(16, 16, AreaSamples: 512));
        var errors = new[] { 1, 4, 16, 64 }.Select(s => Error(Render(Area, EngineKind.Classical, 1, new RenderOptions(16, 16, AreaSamples: s)), reference)).ToArray();
        for (var k = 1; k < errors.Length; k++) Assert.True(errors[k] * 1.5 <= errors[k - 1], string.Join(", ", errors));
        Assert.True(errors[^1] * 10 <= errors[0], string.Join(", ", errors));
    }

    [Fact]
    public void ClassicalIndirectLightConvergesToTheManyVplReference()
    {
        // From 4 VPLs on (one VPL mostly sees unlit stone and is too heavy-tailed to rank): each 4x more VPLs
        // must cut the RMS error against 256 VPLs at least 1.5x (plain Monte Carlo: 2x). Fixed seed.
        var reference = Render(Temple, EngineKind.Classical, 1, new RenderOptions(12, 12, Vpl: 256));
        var errors = new[] { 4, 16, 64 }.Select(v => Error(Render(Temple, EngineKind.Classical, 1, new RenderOptions(12, 12, Vpl: v)), reference)).ToArray();
        for (var k = 1; k < errors.Length; k++) Assert.True(errors[k] * 1.5 <= errors[k - 1], string.Join(", ", errors));
    }

    [Fact]
    public void PipelineTricksKeepTheClassicalImage()
    {
        var tricks = new RenderOptions(16, 16, Neighbours: true, ShadowNeighbours: true, Stop: StopMode.Exact, LatticeLevels: 2);
        foreach (var (scene, options) in new[] { (Area, tricks with { AreaSamples = 4 }), (Temple, tricks with { Vpl = 2 }) })
        {
            var plain = Render(scene, EngineKind.Classical, 1, options with { Neighbours = false, ShadowNeighbours = false, Stop = StopMode.Off, LatticeLevels = 0 });
            var optimised = Render(scene, EngineKind.Classical, 1, options);
            Assert.Equal(plain.Image.Pixels.ToArray(), optimised.Image.Pixels.ToArray());
            Assert.True(optimised.Passes[^1].UpdatedPixels > 0, "gathering ran on the last sampled-light pass");
        }
    }

    [Fact]
    public void OccluderGatheringNeverMarksAVisibleAreaSampleOccluded()
    {
        // The area pass's own rays and layout (a channel per light and sample index), on the analytic engine
        // with gathering, a lattice and termination: every ray reported occluded must have an occluder.
        const int size = 20;
        var geometry = new SceneGeometry(Area);
        var camera = CameraRays.For(Area.Camera, size, size);
        var points = new List<SurfacePoint>();
        for (var pixel = 0; pixel < camera.Length; pixel++)
            if (BruteForceClosest(RayTable.Build(geometry, camera[pixel])) is { } p)
                points.Add(SurfacePoint.Of(pixel, camera[pixel], Hit.From(RayTable.Build(geometry, camera[pixel]), p), Area.Primitives[p], 1));
        var connections = AreaLightPass.Connections(Area, points, points.Count, 8, 0, 8, 1);
        var rays = connections.Select(c => c.Sample.Ray).ToArray();
        var layout = new PixelLayout(size, size, connections.Select(c => points[c.Point].Pixel).ToArray(), connections.Select(c => c.Channel).ToArray());
        var random = new SeededRandom(2);
        using var search = new QuantumHitSearch(new AnalyticEngine(random.Fork(RandomStreams.Engine)), random.Fork(RandomStreams.Search), new QSearchOptions());
        var options = new PassOptions(2, Neighbours: layout, Stop: new StopRule(0.05, random.Fork(RandomStreams.Stop)),
            Lattice: new LatticePlan(2, ConfirmationPlanner.Cheapest(geometry.Count, ConfirmationPlanner.MaxT, 0.4)));
        var (occluded, metrics) = DirectPass.Run(AreaLightPass.Name, search, geometry, rays, options);
        var truth = rays.Select(r => RayTable.Build(geometry, r) is var t && t.Marked(t.FullRange).MarkedCount > 0).ToArray();
        for (var i = 0; i < rays.Length; i++)
            if (occluded[i]) Assert.True(truth[i], $"ray {i} marked occluded but nothing blocks it");
        Assert.True(metrics.UpdatedPixels > 0, "gathering found occluders");
        Assert.True(truth.Count(t => t) > 10, "the case has occluded samples");
    }
}
