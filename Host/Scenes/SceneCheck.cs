using QuantumRayTracing.Scenes.Meshes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Scenes;

/// <summary>
/// `scenes check`: each file loaded and validated; what a good one holds on one line, a bad one's first problem on another.
/// A mesh file (.obj, .gltf, .glb: <see cref="MeshReader"/>) is read as a mesh and put on its grid (<see cref="MeshCheck"/>);
/// any other file is read as a scene. A mesh reader's warnings go to the error writer as "warning: ..." lines.
/// </summary>
public static class SceneCheck
{
    /// <returns>How many files failed.</returns>
    public static int Run(IEnumerable<FileInfo> files, TextWriter output, TextWriter errors)
    {
        var failures = 0;
        foreach (var file in files)
        {
            try
            {
                if (MeshReader.IsMeshFile(file.FullName))
                {
                    var mesh = MeshCheck.Run(file.FullName);
                    foreach (var warning in mesh.File.Warnings) errors.WriteLine($"warning: {warning}");
                    output.WriteLine($"{file}: ok: {MeshCheck.Summary(mesh)}");
                }
                else
                {
                    var scene = SceneLoader.Load(file.FullName);
                    foreach (var warning in scene.Quantisation?.Warnings ?? []) errors.WriteLine($"warning: {warning}");
                    output.WriteLine($"{file}: ok: {Summary(scene)}");
                }
            }
            catch (Exception e) when (e is SceneError or MeshError)
            {
                errors.WriteLine($"error: {e.Message}");
                failures++;
            }
        }
        return failures;
    }

    /// <summary>Name, primitives by kind with their index register, lights by kind, size and grid; for triangles, how they reached the grid.</summary>
    public static string Summary(Scene scene)
    {
        var rectangles = scene.Primitives.Count(p => p is Rectangle);
        var triangles = scene.Primitives.Count - rectangles;
        var kinds = triangles == 0 ? $"{rectangles} rectangles" : $"{rectangles} rectangles and {triangles} triangles";
        return $"'{scene.Name}', {kinds} ({SearchRegisters.For(scene.Primitives.Count).IndexQubits} index qubits), {scene.Lights.Count} point, {scene.AreaLights.Count} area and {scene.DirectionalLights.Count} directional lights, {scene.Width}x{scene.Height}, {scene.Grid}"
            + (scene.Quantisation is { } q ? $"; {q.Describe(scene.Grid)}" : "");
    }
}
