namespace QuantumRayTracing.Scenes.Meshes;

/// <summary>The errors a mesh file gives before its contents are read: missing, a directory, unreadable.</summary>
internal static class FileChecks
{
    public static void ThrowIfNotAFile(string path)
    {
        // Reading a directory fails with "access denied", which sends the user looking at permissions.
        if (Directory.Exists(path)) throw new MeshError(path, "file", "is a directory, not a mesh file");
        if (!File.Exists(path)) throw new MeshError(path, "file", "not found");
    }

    public static MeshError Unreadable(string path, Exception e) =>
        new(path, "file", e is FileNotFoundException or DirectoryNotFoundException ? "not found" : $"cannot be read ({FirstLine(e.Message)})");

    public static string FirstLine(string message)
    {
        var end = message.IndexOfAny(['\r', '\n']);
        return end < 0 ? message : message[..end];
    }
}
