namespace QuantumRayTracing.Output;

/// <summary>
/// The checks every file a command writes passes before any work starts: its directory exists and accepts
/// new files, it is not a directory, and an existing file there is replaced only if this program wrote it.
/// </summary>
public static class OutputFile
{
    /// <summary>
    /// Throws a <see cref="UserError"/> starting with <paramref name="path"/> when it may not be written;
    /// <paramref name="ours"/> tells a file this program wrote, <paramref name="notOurs"/> is the problem otherwise.
    /// </summary>
    public static void EnsureReplaceable(string path, Func<string, bool> ours, string notOurs)
    {
        var full = Path.GetFullPath(path);
        var directory = Path.GetDirectoryName(full)!;
        if (!Directory.Exists(directory))
            throw new UserError($"{path}: directory {directory} does not exist");
        if (Directory.Exists(full))
            throw new UserError($"{path}: is a directory");
        if (File.Exists(full) && !ours(full))
            throw new UserError($"{path}: {notOurs}");
        if (AtomicFile.CannotCreateBeside(full) is { } reason)
            throw new UserError($"{path}: cannot write in directory {directory}: {reason}");
    }
}
