using QuantumRayTracing.Rendering;
using QuantumRayTracing.Search;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Rendering;

public sealed class PipelineOnClassicalEngineTests
{
    [Fact]
    public void EveryPipelineTrickKeepsTheClassicalImage()
    {
        // The classical engine's answers are certain, so gathering, lattice order and stop rule may cost
        // more or less but must not change a pixel.
        var scene = Load("qornell-16.json");
        var plain = new RenderOptions(24, 24);
        var tricks = plain with { Neighbours = true, ShadowNeighbours = true, Stop = StopMode.Exact, LatticeLevels = 3 };
        using var classical = new ClassicalHitSearch();
        var a = SceneRenderer.Render(scene, classical, plain);
        var b = SceneRenderer.Render(scene, classical, tricks);
        Assert.Equal(a.Image.Pixels.ToArray(), b.Image.Pixels.ToArray());
        Assert.True(b.Total.UpdatedPixels > 0);
    }
}
