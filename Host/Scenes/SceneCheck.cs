using QuantumRayTracing.Search;

namespace QuantumRayTracing.Scenes;

/// <summary>`scenes check`: each file loaded and validated; what a good one holds on one line, a bad one's first problem on another.</summary>
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
                output.WriteLine($"{file}: ok: {Summary(SceneLoader.Load(file.FullName))}");
            }
            catch (SceneError e)
            {
                errors.WriteLine($"error: {e.Message}");
                failures++;
            }
        }
        return failures;
    }

    /// <summary>Name, primitives with their index register, lights by kind, size and grid.</summary>
    public static string Summary(Scene scene) =>
        $"'{scene.Name}', {scene.Rectangles.Count} rectangles ({SearchRegisters.For(scene.Rectangles.Count).IndexQubits} index qubits), {scene.Lights.Count} point, {scene.AreaLights.Count} area and {scene.DirectionalLights.Count} directional lights, {scene.Width}x{scene.Height}, {scene.Grid}";
}
