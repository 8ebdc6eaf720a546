using QuantumRayTracing.Scenes.Meshes;

namespace QuantumRayTracing.Scenes.Generation;

/// <summary>The scene rendered when none is named: the Qornell box of the paper's figure 1.</summary>
public static class DefaultScene
{
    public const int QornellPrimitives = 64;

    /// <summary>The name outputs take after it, as a scene file's stem.</summary>
    public static string Stem => $"qornell-{QornellPrimitives}";

    /// <summary>The stem default output names start with: the input file's name without extension, or the built-in scene's.</summary>
    public static string StemOf(string? inputFile) => inputFile is null ? Stem : Path.GetFileNameWithoutExtension(inputFile);

    /// <summary>The scene file, a bare model file framed as a scene (<see cref="ModelScene"/>), or the built-in Qornell box when none is named.</summary>
    public static Scene Load(FileInfo? file) => file is null
        ? SceneLoader.Parse(QornellBox.Build(QornellPrimitives).ToJson(), $"built-in {Stem}")
        : MeshReader.IsMeshFile(file.FullName) ? ModelScene.Load(file.FullName) : SceneLoader.Load(file.FullName);
}
