namespace QuantumRayTracing.Scenes;

/// <summary>A scene file that cannot be used: names the file, the element (a JSON path) and the problem, on one line.</summary>
public sealed class SceneError(string file, string element, string problem)
    : Exception($"{file}: {element}: {problem}")
{
    public string File { get; } = file;
    public string Element { get; } = element;
    public string Problem { get; } = problem;
}
