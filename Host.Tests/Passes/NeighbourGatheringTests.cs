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
}
