namespace QuantumRayTracing.Scenes;

/// <summary>The repository's scene directory, found from a directory inside the repository.</summary>
public static class RepositoryScenes
{
    /// <summary>Scenes/ of the repository (the directory holding QuantumRayTracing.sln) at or above <paramref name="start"/>, or null.</summary>
    public static string? Find(string start)
    {
        for (var directory = new DirectoryInfo(start); directory is not null; directory = directory.Parent)
        {
            var scenes = Path.Combine(directory.FullName, "Scenes");
            if (File.Exists(Path.Combine(directory.FullName, "QuantumRayTracing.sln")) && Directory.Exists(scenes)) return scenes;
        }
        return null;
    }
}
