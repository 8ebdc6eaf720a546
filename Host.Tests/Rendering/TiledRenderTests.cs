using QuantumRayTracing.Engines;
using QuantumRayTracing.Metrics;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Scenes;
using QuantumRayTracing.Tests.Statistics;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Rendering;

/// <summary>
/// Tiled renders (<see cref="TiledRender"/>) on small images cut into small tiles, so that every tile edge, border and
/// clipped corner occurs: the tiles cover the image once, certain engines give the untiled image byte for byte, and the
/// analytic engine's tiles are reproducible and keep the budget.
/// </summary>
public class TiledRenderTests
{
    private static readonly Scene Qornell = Load("qornell-64.json");

    [Theory]
    [InlineData(96, 80, 32, 16)]
    [InlineData(100, 70, 32, 8)]
    [InlineData(64, 64, 64, 16)]
    public void TilesOwnEveryPixelOnceAndTraceTheirBorderOnTheLattice(int width, int height, int size, int border)
    {
        var tiles = ImageTiles.Of(width, height, size, border);
        var owners = new int[width * height];
        foreach (var tile in tiles)
        {
            var (own, traced) = (tile.Interior, tile.Traced);
            for (var y = own.Y; y < own.Y + own.Height; y++)
                for (var x = own.X; x < own.X + own.Width; x++) owners[y * width + x]++;
            Assert.Equal(Math.Max(0, own.X - border), traced.X);
            Assert.Equal(Math.Max(0, own.Y - border), traced.Y);
            Assert.Equal(Math.Min(width, own.X + own.Width + border), traced.X + traced.Width);
            Assert.Equal(Math.Min(height, own.Y + own.Height + border), traced.Y + traced.Height);
            Assert.Equal(0, traced.X % border);
            Assert.Equal(0, traced.Y % border);
        }
        Assert.All(owners, n => Assert.Equal(1, n));
    }

    /// <summary>A window's camera rays are the whole image's rays of its pixels, bit for bit.</summary>
    [Fact]
    public void AWindowsCameraRaysAreTheImagesRays()
    {
        var whole = CameraRays.For(Qornell.Camera, 40, 30);
        var window = CameraRays.Computed(Qornell.Camera, new ImageWindow(8, 16, 24, 10, 40, 30));
        for (var y = 0; y < 10; y++)
            for (var x = 0; x < 24; x++) Assert.Equal(whole[(16 + y) * 40 + 8 + x], window[y * 24 + x]);
        Assert.Throws<ArgumentOutOfRangeException>(() => CameraRays.Computed(Qornell.Camera, new ImageWindow(20, 0, 24, 10, 40, 30)));
    }

    private static RenderResult Tiled(Scene scene, EngineKind kind, RenderOptions options, int tileSize = 32) =>
        TiledRender.Render(new LocalParts(scene, new EngineSetup(kind)), options, tileSize: tileSize);

    private static RenderResult Whole(Scene scene, EngineKind kind, RenderOptions options) =>
        Renderer.Render(scene, new EngineSetup(kind), options);

    /// <summary>Brute force and the BVH answer every search for certain: tiles change none of their pixels.</summary>
    [Theory]
    [InlineData(EngineKind.Classical)]
    [InlineData(EngineKind.Bvh)]
    public void CertainEnginesGiveTheUntiledImage(EngineKind kind)
    {
        var options = RenderDefaults.Options(96, 80, 3);
        Assert.Equal(Whole(Qornell, kind, options).Image.Pixels.ToArray(), Tiled(Qornell, kind, options).Image.Pixels.ToArray());
    }

    /// <summary>The analytic engine's tiles draw from seeds of their own: the same seed gives the same image, another seed another.</summary>
    [Fact]
    public void AnalyticTilesAreReproducible()
    {
        var options = RenderDefaults.Options(96, 80, 5);
        var (first, again) = (Tiled(Qornell, EngineKind.Analytic, options), Tiled(Qornell, EngineKind.Analytic, options));
        Assert.Equal(first.Image.Pixels.ToArray(), again.Image.Pixels.ToArray());
        Assert.Equal(first.Total.IntersectionsConservative, again.Total.IntersectionsConservative);
        var other = Tiled(Qornell, EngineKind.Analytic, options with { Seed = 6 });
        Assert.NotEqual(first.Total.IntersectionsConservative, other.Total.IntersectionsConservative);
        Assert.NotEqual(TiledRender.TileSeed(5, 0), TiledRender.TileSeed(5, 1));
    }

    /// <summary>
    /// Tiled analytic renders keep the budget: every render's expectation within 0.1 % of its pixels, and the wrong pixels of
    /// 12 broad random scenes at 128x128 in tiles of 32 within the upper 1e-4 Poisson tail of their summed expectation.
    /// </summary>
    [Fact]
    public void TiledAnalyticRendersKeepTheBudget()
    {
        var (wrong, expected) = (0L, 0.0);
        for (var j = 0; j < 12; j++)
        {
            var seed = (ulong)(9000 + j);
            var scene = BroadRandomScene.Build(BroadRandomScene.Kinds[j % BroadRandomScene.Kinds.Length], seed);
            var options = RenderDefaults.Options(128, 128, seed);
            var render = Tiled(scene, EngineKind.Analytic, options);
            Assert.False(render.Budget.Exceeded, $"{scene.Name}: over budget");
            Assert.True(render.Budget.ExpectedShare <= AccuracyBudget.Target * (1 + 1e-9), $"{scene.Name}: expected {render.Budget.ExpectedShare:P3}");
            wrong += ImageError.Between(render.Image, Whole(scene, EngineKind.Classical, RenderDefaults.Reference(options)).Image).DifferentPixels;
            expected += render.Budget.ExpectedWrongPixels;
        }
        Assert.True(wrong <= StatisticalBounds.PoissonUpper(expected, 1e-4), $"{wrong} wrong pixels, expected {expected:0.0}");
    }

    /// <summary>A tiled render counts every traced ray once per tile that traces it: border rays add to #Rays, not to the image.</summary>
    [Fact]
    public void BorderRaysAreCountedInEveryTileThatTracesThem()
    {
        var options = RenderDefaults.Options(96, 80, 3);
        var primary = Tiled(Qornell, EngineKind.Classical, options).Passes.Single(p => p.Name == "primary");
        var traced = ImageTiles.Of(96, 80, 32, 1 << options.LatticeLevels).Sum(t => t.Traced.Pixels);
        Assert.Equal(traced, primary.Rays);
    }
}
