namespace QuantumRayTracing.Output;

/// <summary>
/// Writes a whole file or nothing: the bytes go to a uniquely named temporary file beside the
/// target (never an existing file) and are renamed over the target, so a failure never leaves a
/// partial file, and the temporary file is removed on failure.
/// </summary>
public static class AtomicFile
{
    public static void WriteAllBytes(string path, byte[] bytes) => WriteAll([(path, bytes)]);

    /// <summary>
    /// Writes several files as one step: every file goes to its temporary name first, and only when
    /// all are written are they renamed over their targets, so a failure (a full disk) leaves none of
    /// them, not the first few.
    /// </summary>
    public static void WriteAll(IReadOnlyList<(string Path, byte[] Bytes)> files)
    {
        var temporaries = new List<string>();
        try
        {
            foreach (var (path, bytes) in files)
            {
                ArgumentException.ThrowIfNullOrEmpty(path);
                // A name nobody else uses, beside the target so the rename stays on one file system.
                var temporary = Path.Combine(Path.GetDirectoryName(Path.GetFullPath(path))!, $".{Path.GetFileName(path)}.{Guid.NewGuid():N}.tmp");
                temporaries.Add(temporary);
                File.WriteAllBytes(temporary, bytes);
            }
            for (var k = 0; k < files.Count; k++) File.Move(temporaries[k], files[k].Path, overwrite: true);
        }
        catch
        {
            foreach (var temporary in temporaries) DeleteQuietly(temporary);
            throw;
        }
    }

    /// <summary>
    /// Null when a new file can be created beside <paramref name="path"/> (what <see cref="WriteAllBytes"/> needs),
    /// otherwise why not. Tries it: creates a uniquely named empty file there and deletes it, because permission
    /// bits alone do not tell (root ignores them; read-only mounts and /proc refuse new files whatever they say).
    /// </summary>
    public static string? CannotCreateBeside(string path)
    {
        var probe = Path.Combine(Path.GetDirectoryName(Path.GetFullPath(path))!, $".qrt-probe.{Guid.NewGuid():N}.tmp");
        try
        {
            using (new FileStream(probe, FileMode.CreateNew, FileAccess.Write, FileShare.None, 1, FileOptions.DeleteOnClose)) { }
            return null;
        }
        catch (UnauthorizedAccessException)
        {
            return "permission denied";
        }
        catch (FileNotFoundException)
        {
            // What Linux reports (ENOENT) for a new file in /proc and similar directories that hold no ordinary files.
            return "the file system does not allow new files there";
        }
        catch (IOException e)
        {
            return e.Message;
        }
    }

    private static void DeleteQuietly(string path)
    {
        // Cleanup after a failure: the original exception is the one worth reporting, not a second one from here.
        try { File.Delete(path); }
        catch (IOException) { }
        catch (UnauthorizedAccessException) { }
    }
}
