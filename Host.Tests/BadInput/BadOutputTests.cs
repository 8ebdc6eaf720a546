using QuantumRayTracing.Output;

namespace QuantumRayTracing.Tests.BadInput;

/// <summary>
/// A valid scene (or image) with an output the command must refuse before any work: a missing or read-only
/// directory, the input itself, a directory, and image sizes no render can have. The error names the output
/// path; nothing is left behind, neither the image nor the temporary file it is written to before the rename.
/// </summary>
[Collection(BadInputCollection.Name)]
public sealed class BadOutputTests : IDisposable
{
    private static readonly string Scene = Corpus.Scene("valid.json");

    private readonly ScratchDirectory _output = new("qrt-bad-output-");

    public void Dispose() => _output.Dispose();

    private static Outcome Render(string output, string size = "4") =>
        Outcome.Of("render", Scene, "-e", "classical", "--size", size, "-o", output);

    [Fact]
    public void MissingDirectory()
    {
        var output = Path.Combine(_output.Path, "missing", "out.png");
        Render(output).AssertBadInput(output, "", "directory", _output.Path);
    }

    /// <summary>
    /// A directory nobody may create files in. The tests run as root, which ignores a directory's mode bits, so
    /// this uses /proc/self: it exists, and the kernel refuses every new file there, to root too.
    /// </summary>
    [LinuxFact("/proc/self, where root cannot create files")]
    public void ReadOnlyDirectory()
    {
        const string output = "/proc/self/qrt-out.png";
        Render(output).AssertBadInput(output, "", "cannot write in directory /proc/self", null);
        Assert.False(File.Exists(output));
    }

    /// <summary>
    /// A directory whose permissions refuse new files, to root too (which ignores mode bits, so chmod 555 would
    /// test nothing here): sysfs answers EACCES to every file created in its root.
    /// </summary>
    [LinuxFact("sysfs, whose root refuses new files to root too")]
    public void DirectoryWithoutWritePermission()
    {
        const string output = "/sys/qrt-out.png";
        Render(output).AssertBadInput(output, "", "cannot write in directory /sys: permission denied", null);
        Assert.False(File.Exists(output));
    }

    /// <summary>The output path is the scene's own: refused, and the scene keeps its bytes.</summary>
    [Fact]
    public void OutputWouldOverwriteTheScene()
    {
        var scene = _output.File("scene.json");
        File.Copy(Scene, scene);
        var before = File.ReadAllBytes(scene);
        Outcome.Of("render", scene, "-e", "classical", "--size", "4", "-o", scene)
            .AssertBadInput(scene, "", "is an input of this command and would be overwritten", null);
        Assert.Equal(before, File.ReadAllBytes(scene));
        Assert.Equal(["scene.json"], Directory.GetFileSystemEntries(_output.Path).Select(Path.GetFileName));
    }

    /// <summary>The same for `supersample --image`: the output would replace the picture being supersampled.</summary>
    [Fact]
    public void OutputWouldOverwriteTheImage()
    {
        var image = _output.File("in.png");
        File.Copy(Corpus.Image("valid.png"), image);
        var before = File.ReadAllBytes(image);
        Outcome.Of("supersample", "--image", image, "--subpixels", "2", "-m", "mc", "-o", image)
            .AssertBadInput(image, "", "is an input of this command and would be overwritten", null);
        Assert.Equal(before, File.ReadAllBytes(image));
        Assert.Equal(["in.png"], Directory.GetFileSystemEntries(_output.Path).Select(Path.GetFileName));
    }

    /// <summary>A derived output (--reference writes out-reference.png) that would land on the scene counts too.</summary>
    [Fact]
    public void ReferenceImageWouldOverwriteTheScene()
    {
        var scene = _output.File("out-reference.png");
        File.Copy(Scene, scene);
        var output = _output.File("out.png");
        Outcome.Of("render", scene, "-e", "classical", "--size", "4", "--reference", "-o", output)
            .AssertBadInput(scene, "", "is an input of this command and would be overwritten", null);
        Assert.Equal(["out-reference.png"], Directory.GetFileSystemEntries(_output.Path).Select(Path.GetFileName));
    }

    [Fact]
    public void OutputIsADirectory()
    {
        var output = _output.File("out.png");
        Directory.CreateDirectory(output);
        Render(output).AssertBadInput(output, "", "is a directory", null);
        Assert.Empty(Directory.GetFileSystemEntries(output));
        Assert.Equal(["out.png"], Directory.GetFileSystemEntries(_output.Path).Select(Path.GetFileName));
    }

    /// <summary>Image size on the command line rather than in the file: an option's value, so a usage error (exit 1).</summary>
    [Theory]
    [InlineData("0", "got 0x0")]
    [InlineData("1000000", "got 1000000x1000000")]
    [InlineData("0x8", "got 0x8")]
    public void ImpossibleSize(string size, string problem) =>
        Render(_output.File("out.png"), size).AssertUsageError("--size", problem, _output.Path);

    /// <summary>
    /// A write that fails after the checks passed (a full disk, a directory made read-only meanwhile) is still
    /// one line naming the output, not an exception; written here straight into /proc/self, which refuses it.
    /// </summary>
    [LinuxFact("/proc/self, where root cannot create files")]
    public void WriteFailureAfterTheChecksIsAUserError()
    {
        const string output = "/proc/self/qrt-late.png";
        var error = Assert.Throws<UserError>(() => ImageFiles.Write([(new RgbImage(1, 1), output)]));
        Assert.StartsWith($"{output}: cannot be written", error.Message);
        Assert.DoesNotContain('\n', error.Message);
    }
}
