using QuantumRayTracing.Estimates;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Generation;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Estimates;

/// <summary>Which ray an estimate is made for: a pixel's camera ray, or the widest oracle of the image.</summary>
public sealed class EstimateRayTests
{
    [Fact]
    public void WorstCaseIsTheFirstPixelOfTheWidestOracle()
    {
        var scene = Load("qornell-8.json");
        var geometry = new SceneGeometry(scene);
        const int size = 12;
        var (input, label) = EstimateRay.WorstCase(scene, geometry, size, size, OracleConstruction.Compact);
        var keys = CameraRays.For(scene.Camera, size, size).Select(ray =>
        {
            var table = RayTable.Build(geometry, ray);
            var registers = OracleRegisters.For(new OracleInput(table, table.FullRange) { Construction = OracleConstruction.Compact });
            return (registers.PeakQubits, registers.DepthQubits);
        }).ToArray();
        var chosen = Array.FindIndex(CameraRays.For(scene.Camera, size, size), r => r == input.Table.Ray);
        Assert.True(chosen >= 0);
        Assert.Equal($"worst case: pixel ({chosen % size}, {chosen / size}) of {size}x{size}", label);
        Assert.All(keys, k => Assert.True(k.CompareTo(keys[chosen]) <= 0, $"{k} is wider than the chosen {keys[chosen]}"));
        Assert.All(keys[..chosen], k => Assert.True(k.CompareTo(keys[chosen]) < 0, "an earlier pixel is as wide"));
        // The rays differ: not every pixel is a worst case, or the choice would be trivial.
        Assert.Contains(keys, k => k.CompareTo(keys[chosen]) < 0);
    }

    [Fact]
    public void PixelRayIsThatPixelsCameraRayOverItsFullRange()
    {
        var scene = SceneLoader.Parse(SweepScene.Build(8, 3).ToJson(), "sweep.json");
        var (input, label) = EstimateRay.Pixel(scene, new SceneGeometry(scene), 6, 4, 5, 2, OracleConstruction.Baseline);
        Assert.Equal(CameraRays.For(scene.Camera, 6, 4)[2 * 6 + 5], input.Table.Ray);
        Assert.Equal(input.Table.FullRange, input.Window);
        Assert.Equal(OracleConstruction.Baseline, input.Construction);
        Assert.Equal("pixel (5, 2) of 6x4", label);
    }

    [Theory]
    [InlineData(1, 2)]
    [InlineData(4, 2)]
    [InlineData(512, 4)]
    [InlineData(64, 8)]
    public void SweepScenesHaveTheirSizeAndGrid(int primitives, int bits)
    {
        var scene = SceneLoader.Parse(SweepScene.Build(primitives, bits).ToJson(), "sweep.json");
        Assert.Equal(primitives, scene.Primitives.Count);
        Assert.Equal(new CoordinateGrid(bits, 0), scene.Grid);
        // Camera rays must meet primitives, or the estimates would be of an empty search.
        var geometry = new SceneGeometry(scene);
        var hits = CameraRays.For(scene.Camera, 8, 8).Count(ray => RayTable.Build(geometry, ray).Marked(HitWindow.Range(0, Ray.Unbounded, primitives)).MarkedCount > 0);
        Assert.True(hits > 0);
    }
}
