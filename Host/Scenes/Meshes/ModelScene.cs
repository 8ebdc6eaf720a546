using System.Globalization;

namespace QuantumRayTracing.Scenes.Meshes;

/// <summary>
/// A bare model file (.obj, .gltf, .glb) as a scene, for <c>qrt render model.obj</c>: the model scaled to
/// <see cref="Size"/> units across, stood on a square floor twice as wide, a camera in front of it and a little above,
/// framed on its bounds, and one point light above and to the front left. The scene is written as a scene file's text
/// (<see cref="Scene.FramingText"/>) and loaded from it, so what a render prints is a file the user can copy and edit.
/// </summary>
public static class ModelScene
{
    /// <summary>The model's largest side after scaling, in world units.</summary>
    public const double Size = 16;

    /// <summary>The camera's vertical field of view, degrees.</summary>
    public const double VerticalFov = 40;

    public static Scene Load(string path)
    {
        var read = MeshReader.Read(path);
        var (mesh, zeroArea) = read.Mesh.WithoutDegenerate();
        if (mesh.Triangles.Count == 0)
            throw new MeshError(path, "triangles", zeroArea == 1 ? "the only triangle has zero area" : $"all {zeroArea} triangles have zero area");
        var (min, max) = mesh.Bounds;
        var scale = Size / mesh.Extent;
        var world = 2 * (int)Size + 2;
        // Scaled about the origin, then moved so the model stands on the floor (y = 1) at its centre.
        var centre = new Vec3(world / 2.0, 1 + scale * (max.Y - min.Y) / 2, world / 2.0);
        var translate = new Vec3(centre.X - scale * (min.X + max.X) / 2, 1 - scale * min.Y, centre.Z - scale * (min.Z + max.Z) / 2);
        // Far enough that the bounds' sphere fills about 85 % of the view's height.
        var radius = scale * (max - min).Length / 2;
        var distance = radius / Math.Sin(VerticalFov * Math.PI / 360) / 0.85;
        var camera = centre + distance * new Vec3(0, 0.35, -1).Normalized();
        var light = centre + distance * new Vec3(-0.5, 1, -0.6).Normalized();
        var intensity = (light - centre).Dot(light - centre);
        var text = Invariant($$"""
            {
              "name": "{{Path.GetFileName(path)}} on a floor",
              "image": { "width": 128, "height": 128 },
              "camera": { "position": {{V(camera)}}, "lookAt": {{V(centre)}}, "verticalFov": {{VerticalFov}} },
              "ambient": 0.1,
              "materials": { "floor": { "diffuse": [0.7, 0.7, 0.7] }, "model": { "diffuse": [0.8, 0.65, 0.5] } },
              "lights": [ { "position": {{V(light)}}, "intensity": [{{R(intensity)}}, {{R(intensity)}}, {{R(intensity)}}] } ],
              "rectangles": [ { "min": [0, 1, 0], "max": [{{world}}, 1, {{world}}], "material": "floor" } ],
              "meshes": [ { "file": "{{Path.GetFileName(path)}}", "material": "model", "translate": {{V(translate)}}, "scale": {{R(scale)}} } ]
            }
            """);
        // Named as a scene file beside the model, so the mesh's path resolves and errors name both.
        var scene = SceneLoader.Parse(text, Path.Combine(Path.GetDirectoryName(Path.GetFullPath(path)) ?? "", Path.GetFileName(path) + ".scene.json"));
        return scene with { FramingText = text };
    }

    private static string V(Vec3 v) => Invariant($"[{R(v.X)}, {R(v.Y)}, {R(v.Z)}]");

    // Six significant digits: a file a person reads; the scene is loaded from the same text.
    private static string R(double value) => value.ToString("G6", CultureInfo.InvariantCulture);

    private static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
