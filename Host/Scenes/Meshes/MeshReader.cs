namespace QuantumRayTracing.Scenes.Meshes;

/// <summary>Reads a mesh file by its extension: <c>.obj</c> (<see cref="ObjReader"/>), <c>.gltf</c> or <c>.glb</c> (<see cref="GltfReader"/>).</summary>
public static class MeshReader
{
    public static IReadOnlyList<string> Extensions { get; } = [".obj", ".gltf", ".glb"];

    /// <summary>Whether <paramref name="path"/> has a mesh file's extension (any letter case).</summary>
    public static bool IsMeshFile(string path) => Extensions.Contains(Path.GetExtension(path).ToLowerInvariant());

    public static MeshFile Read(string path) => Path.GetExtension(path).ToLowerInvariant() switch
    {
        ".obj" => ObjReader.Read(path),
        ".gltf" or ".glb" => GltfReader.Read(path),
        var other => throw new MeshError(path, "file",
            $"{(other.Length == 0 ? "has no extension" : $"the extension '{other}' is not a mesh format")}: mesh files are read by extension, one of {string.Join(", ", Extensions)}"),
    };
}
