using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using QuantumRayTracing.Search.Bvh;
using QuantumRayTracing.Tests.Scenes;

namespace QuantumRayTracing.Tests.Search.Bvh;

/// <summary>
/// The BVH engine gives brute force's answer for every ray and window, with far fewer tests on large scenes,
/// and renders the classical image byte for byte.
/// </summary>
public class BvhHitSearchTests
{
    public static TheoryData<BroadSceneKind, ulong> Scenes()
    {
        var data = new TheoryData<BroadSceneKind, ulong>();
        foreach (var kind in BroadRandomScene.Kinds)
            foreach (var seed in new ulong[] { 1, 2, 3 })
                data.Add(kind, seed);
        return data;
    }

    /// <summary>
    /// Camera rays, and rays from their hits in random directions that stop short (as shadow rays do) and leave
    /// the primitive they start on, each under its full window and under a random closer-than window: the BVH's
    /// primitive must be brute force's, the smallest accepted (depth, id), in every case.
    /// </summary>
    [Theory]
    [MemberData(nameof(Scenes))]
    public void FindsWhatBruteForceFindsForEveryRayAndWindow(BroadSceneKind kind, ulong seed)
    {
        var scene = BroadRandomScene.Build(kind, seed);
        var geometry = new SceneGeometry(scene);
        var hierarchy = BoundingVolumeHierarchy.Build(geometry);
        var random = new SeededRandom(seed);
        var compared = 0;
        foreach (var camera in CameraRays.For(scene.Camera, 24, 24))
        {
            foreach (var ray in RaysFrom(camera, geometry, random))
            {
                var table = RayTable.Build(geometry, ray);
                var full = table.FullRange;
                var closer = HitWindow.Closer(random.NextInt(0, 4), random.NextInt(0, 1 << geometry.Grid.Bits), random.NextInt(0, geometry.Count), TieBreak.Strict);
                foreach (var window in new[] { full, closer })
                {
                    var expected = BestAccepted.Among(table, window, Enumerable.Range(0, geometry.Count));
                    Assert.Equal(expected, BvhHitSearch.Search(hierarchy, ray, window).Primitive);
                    compared++;
                }
            }
        }
        Assert.True(compared >= 24 * 24 * 2, $"{compared} comparisons");
    }

    // The camera ray, and when it hits, a bounded ray from its hit point in a random direction, leaving that primitive.
    private static IEnumerable<Ray> RaysFrom(Ray camera, SceneGeometry geometry, SeededRandom random)
    {
        yield return camera;
        var table = RayTable.Build(geometry, camera);
        if (BestAccepted.Among(table, table.FullRange, Enumerable.Range(0, geometry.Count)) is not { } hit) yield break;
        var direction = new Vec3(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5);
        yield return new Ray(camera.At(table.Distance(hit)), direction, MaxDistance: 1 + 20 * random.NextDouble(), ExcludedPrimitive: hit);
    }

    /// <summary>
    /// On 1,000 scattered rectangles a camera ray's walk must test fewer than N / 10 boxes and primitives on average
    /// (a walk that culled nothing would test every node and primitive, about 1.5 N), and the build must cost
    /// between N log2 N and 8 N log2 N primitive box reads (4 per primitive and level when balanced).
    /// </summary>
    [Fact]
    public void CullsMostOfALargeSceneAfterAnNLogNBuild()
    {
        const int n = 1000;
        var geometry = new SceneGeometry(BroadRandomScene.Scattered(n, 5));
        var hierarchy = BoundingVolumeHierarchy.Build(geometry);
        var rays = CameraRays.For(BroadRandomScene.Scattered(n, 5).Camera, 32, 32);
        var tests = rays.Select(ray => BvhHitSearch.Search(hierarchy, ray, HitWindow.Range(ray.Near, ray.Far, n)).Tests).Average();
        Assert.True(tests < n / 10.0, $"{tests:F1} tests per ray on N = {n}");
        var nLogN = n * Math.Log2(n);
        Assert.InRange(hierarchy.BuildWork, (long)nLogN, (long)(8 * nLogN));
        Assert.Equal(n, hierarchy.Primitives.Distinct().Count());
    }

    /// <summary>A render on the BVH engine is the classical render byte for byte, and pays the build once per frame.</summary>
    [Fact]
    public void RendersTheClassicalImageAndChargesTheBuildOnce()
    {
        var scene = BroadRandomScene.Build(BroadSceneKind.SmallShadows, 4);
        var options = RenderOptions.PaperPipeline(32, 32, 3);
        var classical = Renderer.Render(scene, new EngineSetup(EngineKind.Classical), options);
        var bvh = Renderer.Render(scene, new EngineSetup(EngineKind.Bvh), options);
        Assert.Equal(classical.Image.Pixels.ToArray(), bvh.Image.Pixels.ToArray());

        using var search = new BvhHitSearch();
        var geometry = new SceneGeometry(scene);
        var queries = CameraRays.For(scene.Camera, 8, 8).Select(r => new HitQuery(RayTable.Build(geometry, r), HitWindow.Range(r.Near, r.Far, geometry.Count))).ToArray();
        var walks = queries.Sum(q => BvhHitSearch.Search(BoundingVolumeHierarchy.Build(geometry), q.Table.Ray, q.Window).Tests);
        var first = search.Run(queries).Sum(o => o.Cost.ClassicalTests);
        var second = search.Run(queries).Sum(o => o.Cost.ClassicalTests);
        Assert.Equal(walks + search.Hierarchy!.BuildWork, first);
        Assert.Equal(walks, second);
    }
}
