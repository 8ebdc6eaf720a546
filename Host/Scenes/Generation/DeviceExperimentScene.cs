using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rays;

using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Generation;

namespace QuantumRayTracing.Scenes.Generation;

/// <summary>
/// The ray tracing paper's device experiment (sec. 8): a minimal scene of 4 primitives on the 16x16x16
/// integer grid, and a primary ray that meets only one of them. Four squares facing z, one per quadrant
/// of the view, at depths 6, 8, 10 and 12; the camera looks along +z from half a unit off the grid.
/// </summary>
public static class DeviceExperimentScene
{
    /// <summary>Pixels per side of the image the ray is taken from.</summary>
    public const int ImageSize = 8;

    public static Scene Build()
    {
        var builder = new SceneBuilder("device experiment, 4 primitives, 4-bit grid", integerBits: 4)
            .Material("white", 0.75, 0.75, 0.75)
            .Camera([7.5, 7.5, 0.5], [7.5, 7.5, 15], 60)
            .Light(7.5, 7.5, 1, 10)
            .Rectangle([1, 1, 6], [7, 7, 6], "white")
            .Rectangle([8, 1, 8], [14, 7, 8], "white")
            .Rectangle([1, 8, 10], [7, 14, 10], "white")
            .Rectangle([8, 8, 12], [14, 14, 12], "white");
        return SceneLoader.Parse(builder.ToJson(), "device-experiment.json");
    }

    /// <summary>
    /// The oracle input of the first camera ray (row-major, <see cref="ImageSize"/> square) whose full-range
    /// search marks exactly one primitive: the ray of the paper's fig. 15.
    /// </summary>
    public static OracleInput Ray()
    {
        var scene = Build();
        var geometry = new SceneGeometry(scene);
        foreach (var ray in CameraRays.For(scene.Camera, ImageSize, ImageSize))
        {
            var table = RayTable.Build(geometry, ray);
            if (table.Marked(table.FullRange).MarkedCount == 1) return new OracleInput(table, table.FullRange);
        }
        throw new InvalidOperationException("no camera ray meets exactly one primitive");
    }
}
