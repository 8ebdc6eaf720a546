namespace QuantumRayTracing.Output;

/// <summary>
/// Writes a whole file or nothing: the bytes go to a uniquely named temporary file beside the
/// target (never an existing file) and are renamed over the target, so a failure never leaves a partial file, and the temporary file is removed on failure.
/// </summary>
public static class AtomicFile
{
    public static void WriteAllBytes(string path, byte[] bytes)
    {
        ArgumentException.ThrowIfNullOrEmpty(path);
        // A name nobody else uses, beside the target so the rename stays on one file system.
        var temporary = Path.Combine(Path.GetDirectoryName(Path.GetFullPath(path))!, $".{Path.GetFileName(path)}.{Guid.NewGuid():N}.tmp");
        try
        {
            File.WriteAllBytes(temporary, bytes);
            File.Move(temporary, path, overwrite: true);
        }
        catch
        {
            DeleteQuietly(temporary);
            throw;
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
