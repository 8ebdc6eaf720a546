using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Passes;

public sealed class NeighbourGatheringTests
{
    private static readonly Scene Depth = Load("depth-complexity-32.json");

    [Fact]
    public void NeighOptNeverMakesAPixelWorse()
    {
        // One quantum round leaves many rays on a farther hit or none; gathering may only move each ray
        // to a hit it accepts that comes earlier in the (depth, id) order.
        const int size = 24;
        var geometry = new SceneGeometry(Depth);
        var rays = CameraRays.For(Depth.Camera, size, size);
        var random = new SeededRandom(4);
        using var search = new QuantumHitSearch(new AnalyticEngine(random.Fork(RandomStreams.Engine)), random.Fork(RandomStreams.Search), new QSearchOptions());
        var (hits, _) = TracePass.Run("primary", search, geometry, rays, new PassOptions(1));
        var before = (Hit?[])hits.Clone();
        var (tests, updated) = NeighbourGathering.ForClosest(geometry, rays, hits, PixelLayout.Image(size, size), TieBreak.Strict);
        var changed = 0;
        for (var i = 0; i < rays.Length; i++)
        {
            if (hits[i] == before[i]) continue;
            changed++;
            var after = hits[i]!.Value;
            Assert.NotNull(RayTable.Test(geometry, rays[i], after.Primitive, RayTable.Build(geometry, rays[i]).FullRange));
            if (before[i] is { } old)
                Assert.True(after.Depth < old.Depth || (after.Depth == old.Depth && after.Primitive < old.Primitive), $"ray {i} moved back");
        }
        Assert.Equal(changed, updated);
        Assert.True(changed > 0 && tests >= changed, $"{changed} changed by {tests} tests: the case should exercise gathering");
    }

    [Fact]
    public void OccluderGatheringNeverMarksAVisibleLightOccluded()
    {
        // Shadow rays from every pixel's first visible point to a light; neighbours offer arbitrary,
        // often wrong, occluders: a ray may only become occluded by a primitive that truly blocks it.
        const int size = 16;
        var geometry = new SceneGeometry(Depth);
        var rays = CameraRays.For(Depth.Camera, size, size)
            .Select(r => new Ray(r.At(3), new Vec3(0.3, 0.2, -1), MaxDistance: 1)).ToArray();
        var random = new SeededRandom(8);
        var occluders = Enumerable.Range(0, rays.Length).Select(_ => random.NextDouble() < 0.5 ? (int?)random.NextInt(geometry.Count) : null).ToArray();
        var offered = (int?[])occluders.Clone();
        NeighbourGathering.ForOcclusion(geometry, rays, occluders, PixelLayout.Image(size, size));
        for (var i = 0; i < rays.Length; i++)
        {
            if (offered[i] is not null || occluders[i] is not { } p) continue;
            Assert.NotNull(RayTable.Test(geometry, rays[i], p, RayTable.Build(geometry, rays[i]).FullRange));
        }
    }

    [Fact]
    public void LatticeLevelsAndCoarserNeighbours()
    {
        var layout = PixelLayout.Image(9, 9);
        int Ray(int x, int y) => y * 9 + x;
        Assert.Equal(2, layout.LatticeLevel(Ray(4, 8), 2));  // both multiples of 4
        Assert.Equal(1, layout.LatticeLevel(Ray(2, 4), 2));  // multiples of 2, not both of 4
        Assert.Equal(0, layout.LatticeLevel(Ray(3, 4), 2));
        Assert.Equal(2, layout.LatticeLevel(Ray(8, 8), 2));  // capped at the levels asked for
        // (2, 4) at level 1: step 2, neighbours at even offsets on the 4-lattice: (0, 4) and (4, 4).
        Assert.Equal([Ray(0, 4), Ray(4, 4)], layout.CoarserNeighbours(Ray(2, 4), 2).Order());
        // (3, 5) at level 0: the 2-lattice pixels around it are the four diagonals.
        Assert.Equal([Ray(2, 4), Ray(4, 4), Ray(2, 6), Ray(4, 6)], layout.CoarserNeighbours(Ray(3, 5), 2).Order());
        // Slots: 2 on a lattice edge's midpoint, 4 at a cell's centre, whatever the border cuts off.
        Assert.Equal(2, layout.CoarserNeighbourSlots(Ray(2, 4), 2));
        Assert.Equal(4, layout.CoarserNeighbourSlots(Ray(3, 5), 2));
        // In a 10x10 image the corner pixel (9, 9) has 4 slots but only (8, 8) inside the image: it cannot be vouched for.
        var wide = PixelLayout.Image(10, 10);
        Assert.Equal(4, wide.CoarserNeighbourSlots(9 * 10 + 9, 2));
        Assert.Equal([8 * 10 + 8], wide.CoarserNeighbours(9 * 10 + 9, 2));
    }

    [Fact]
    public void CoarserNeighboursAreTheNextLatticesPixelsAroundInScanOrder()
    {
        // Every ray of an odd-sized image with up to 3 rays per pixel in 2 channels, against the definition: of the 8
        // pixels at offsets −s, 0, s (s = 2^level) in x and y, scanned row by row, those inside the image whose coordinates
        // are multiples of 2s, each with its ray of the same channel (the last listed), in that order.
        const int width = 37, height = 29, levels = 3;
        var random = new SeededRandom(5);
        var (pixels, channels) = (new List<int>(), new List<int>());
        for (var pixel = 0; pixel < width * height; pixel++)
            for (var k = random.NextInt(4); k > 0; k--)
            {
                pixels.Add(pixel);
                channels.Add(random.NextInt(2));
            }
        var layout = new PixelLayout(width, height, pixels, channels);
        int RayAt(int pixel, int channel) => Enumerable.Range(0, pixels.Count).LastOrDefault(i => pixels[i] == pixel && channels[i] == channel, -1);
        for (var ray = 0; ray < pixels.Count; ray++)
        {
            var (y, x) = Math.DivRem(pixels[ray], width);
            var step = 1 << layout.LatticeLevel(ray, levels);
            var expected = new List<int>();
            for (var dy = -step; dy <= step; dy += step)
                for (var dx = -step; dx <= step; dx += step)
                {
                    var (nx, ny) = (x + dx, y + dy);
                    if ((dx, dy) == (0, 0) || nx < 0 || ny < 0 || nx >= width || ny >= height || nx % (2 * step) != 0 || ny % (2 * step) != 0) continue;
                    if (RayAt(ny * width + nx, channels[ray]) is var neighbour and >= 0) expected.Add(neighbour);
                }
            Assert.Equal(expected, layout.CoarserNeighbours(ray, levels));
        }
    }
}
