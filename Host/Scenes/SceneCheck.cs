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
                else output.WriteLine($"{file}: ok: {Summary(SceneLoader.Load(file.FullName))}");
            }
            catch (Exception e) when (e is SceneError or MeshError)
            {
                errors.WriteLine($"error: {e.Message}");
                failures++;
            }
        }
        return failures;
    }

    /// <summary>Name, primitives with their index register, lights by kind, size and grid.</summary>
    public static string Summary(Scene scene) =>
        $"'{scene.Name}', {scene.Primitives.Count} rectangles ({SearchRegisters.For(scene.Primitives.Count).IndexQubits} index qubits), {scene.Lights.Count} point, {scene.AreaLights.Count} area and {scene.DirectionalLights.Count} directional lights, {scene.Width}x{scene.Height}, {scene.Grid}";
}
