namespace QuantumRayTracing.Output;

/// <summary>
/// The rules for PNGs a command writes: those of every output (<see cref="OutputFile"/>; a PNG is this
/// program's when it carries <see cref="PngWriter.Software"/>), and besides, an output never replaces an
/// input and two outputs of one command never share a path. Checked before any work starts, so a bad path
/// fails fast; the files are written only at the end, all or none.
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
            if (inputPaths.Contains(full))
                throw new UserError($"{output}: is an input of this command and would be overwritten");
            if (!seen.Add(full))
                throw new UserError($"{output}: named for two outputs of this command");
            OutputFile.EnsureReplaceable(output, PngWriter.IsWrittenHere,
                "exists and was not written by this program; choose another output or remove it");
        }
    }

    /// <summary>The file written beside <paramref name="output"/>: out.png → out-reference.png.</summary>
    public static string Beside(string output, string suffix)
    {
        var directory = Path.GetDirectoryName(output) ?? "";
        return Path.Combine(directory, $"{Path.GetFileNameWithoutExtension(output)}-{suffix}{Path.GetExtension(output)}");
    }

    /// <summary>Writes every image to its path, all or none (<see cref="AtomicFile.WriteAll"/>).</summary>
    public static void Write(IEnumerable<(RgbImage Image, string Path)> images)
    {
        var files = images.Select(i => (i.Path, PngWriter.Encode(i.Image))).ToArray();
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
