using QuantumRayTracing.Engines;
using QuantumRayTracing.Experiments;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Generation;

namespace QuantumRayTracing.Tests.Experiments;

/// <summary>`bench bvh-comparison`'s measurement on small frames: brute force costs N, the BVH far less where most of N is out of view.</summary>
public class BvhComparisonExperimentTests
{
    private static readonly BvhComparisonSettings Small = new(16, 1, [8, 512], [64]);

    [Fact]
    public void BruteForceCostsNAndTheBvhCullsTheFillerBehindTheCamera()
    {
        var scene = SceneLoader.Parse(QornellBox.Build(512).ToJson(), "qornell-512");
        var row = BvhComparisonExperiment.Measure("Qornell box 512", scene, Small);
        Assert.Equal(512, row.Primitives);
        Assert.Equal(512.0, row.BruteForce, 9);
        // Every filler square sits behind the camera: a walk tests a few dozen boxes and primitives, not 512.
        Assert.InRange(row.BvhWalks, 1, 50);
        Assert.True(row.BuildWork > 512 * Math.Log2(512), $"build work {row.BuildWork}");
        // The BVH answers every ray as brute force does, so its frame traces the same mirror and shadow rays.
        var bruteForceRays = Renderer.Render(scene, new EngineSetup(EngineKind.Classical), RenderOptions.PaperPipeline(Small.Size, Small.Size, Small.Seed)).Total.Rays;
        Assert.Equal(bruteForceRays, row.Rays);
    }

    [Fact]
    public void MeasuresEveryScenePlannedInOrder()
    {
        var names = BvhComparisonExperiment.Scenes(Small).Select(s => s.Name).ToArray();
        Assert.Equal(["Qornell box 8", "Qornell box 512", "Depth Complexity 32", "Depth Complexity 64", "64 random rectangles"], names);
    }
}
