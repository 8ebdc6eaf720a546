namespace QuantumRayTracing.Output;

/// <summary>
/// Writes a whole file or nothing: the bytes go to <c>path + ".tmp"</c> and are renamed over the
/// target, so a failure never leaves a partial file, and the temporary file is removed on failure.
/// </summary>
public static class AtomicFile
{
    public static void WriteAllBytes(string path, byte[] bytes)
    {
        ArgumentException.ThrowIfNullOrEmpty(path);
        var temporary = path + ".tmp";
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
