using QuantumRayTracing.Cli;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Meshes;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.BadInput;
using QuantumRayTracing.Tests.Cli;

namespace QuantumRayTracing.Tests.Scenes.Meshes;

/// <summary>
/// A bare model file as a scene (`qrt render model.obj`): the model scaled to 16 units and stood on the floor at its
/// centre, the camera's centre ray on it, the text it prints loading to the same scene, and `render` writing the image.
/// </summary>
[Collection(BadInputCollection.Name)]
public sealed class ModelSceneTests : IDisposable
{
    private static readonly string Bunny = Path.Combine(RepositoryPaths.Root, "Host.Tests", "Scenes", "Meshes", "Fixtures", "bunny.obj");

    private readonly ScratchDirectory _dir = new("qrt-model-scene-");

    public void Dispose() => _dir.Dispose();

    [Fact]
    public void TheBunnyStandsOnTheFloorInTheCameraCentre()
    {
        var scene = ModelScene.Load(Bunny);
        Assert.Equal(1 + 3674, scene.Primitives.Count);
        Assert.IsType<Rectangle>(scene.Primitives[0]);
        var corners = scene.Primitives.OfType<Triangle>().SelectMany(t => new[] { t.A, t.B, t.C }).ToArray();
        var step = scene.Grid.Step;
        // Scaled to 16 units across, bottom on the floor (y = 1), centred at x = z = 17, each to a grid step's rounding.
        Assert.Equal(1, corners.Min(c => c.Y), step);
        Assert.Equal(16, Math.Max(corners.Max(c => c.X) - corners.Min(c => c.X), Math.Max(corners.Max(c => c.Y) - corners.Min(c => c.Y), corners.Max(c => c.Z) - corners.Min(c => c.Z))), 2 * step);
        Assert.Equal(17, (corners.Min(c => c.X) + corners.Max(c => c.X)) / 2, step);
        Assert.Equal(17, (corners.Min(c => c.Z) + corners.Max(c => c.Z)) / 2, step);
        var geometry = new SceneGeometry(scene);
        var centre = CameraRays.For(scene.Camera, 9, 9)[4 * 9 + 4];
        var table = RayTable.Build(geometry, centre);
        Assert.True(BestAccepted.Among(table, table.FullRange, Enumerable.Range(0, geometry.Count)) > 0, "the centre ray hits the model");
        var again = SceneLoader.Parse(scene.FramingText!, Path.Combine(Path.GetDirectoryName(Bunny)!, "copy.json"));
        Assert.Equal(scene.Primitives, again.Primitives);
        Assert.Equal((scene.Camera, scene.Grid), (again.Camera, again.Grid));
    }

    [Fact]
    public void RenderTakesAModelFileAtOnce()
    {
        var output = _dir.File("bunny.png");
        var (code, error) = ConsoleCapture.Run("render", Bunny, "--engine", "analytic", "--size", "8", "-o", output);
        Assert.True(code == ExitCodes.Success, error);
        Assert.True(File.Exists(output));
    }
}
