namespace QuantumRayTracing.Scenes.Meshes;

/// <summary>
/// A mesh file that cannot be used: names the file, where in it (an OBJ line such as <c>line 12</c>, a glTF
/// element such as <c>meshes[0].primitives[1]</c>, or <c>file</c>) and the problem, on one line, as
/// <see cref="SceneError"/> does for scene files.
/// </summary>
public sealed class MeshError(string file, string element, string problem)
    : Exception($"{file}: {element}: {problem}")
{
    public string File { get; } = file;
    public string Element { get; } = element;
    public string Problem { get; } = problem;
}
