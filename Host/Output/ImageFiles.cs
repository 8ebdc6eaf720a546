namespace QuantumRayTracing.Output;

/// <summary>
/// The rules for PNGs a command writes: the directory must exist, an existing file is replaced only
/// if this program wrote it (its PNG carries <see cref="PngEncoder.Software"/>), an output never
/// replaces an input, two outputs of one command never share a path, and the directory accepts new
/// files. Checked before any work starts, so a bad path fails fast; the files are written only at the
/// end, each atomically.
/// </summary>
public static class ImageFiles
{
    /// <summary>Throws a <see cref="UserError"/> naming the path when any output may not be written.</summary>
    public static void EnsureWritable(IReadOnlyList<string> outputs, IEnumerable<string> inputs)
    {
        var inputPaths = inputs.Select(Path.GetFullPath).ToHashSet();
        var seen = new HashSet<string>();
        foreach (var output in outputs)
        {
            var full = Path.GetFullPath(output);
            var directory = Path.GetDirectoryName(full)!;
            if (!Directory.Exists(directory))
                throw new UserError($"{output}: directory {directory} does not exist");
            if (inputPaths.Contains(full))
                throw new UserError($"{output}: is an input of this command and would be overwritten");
            if (!seen.Add(full))
                throw new UserError($"{output}: named for two outputs of this command");
            if (Directory.Exists(full))
                throw new UserError($"{output}: is a directory");
            if (File.Exists(full) && !PngEncoder.IsWrittenHere(full))
                throw new UserError($"{output}: exists and was not written by this program; choose another output or remove it");
            if (AtomicFile.CannotCreateBeside(full) is { } reason)
                throw new UserError($"{output}: cannot write in directory {directory}: {reason}");
        }
    }

    /// <summary>Writes every image to its path, all or none (<see cref="AtomicFile.WriteAll"/>).</summary>
    public static void Write(IEnumerable<(RgbImage Image, string Path)> images)
    {
        var files = images.Select(i => (i.Path, PngEncoder.Encode(i.Image))).ToArray();
        // Checked beforehand, but the disk can still fill up or the directory change in between.
        try
        {
            AtomicFile.WriteAll(files);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new UserError($"{string.Join(", ", files.Select(f => f.Path))}: cannot be written: {e.Message}");
        }
    }
}
