using System.Text;

namespace QuantumRayTracing.Tests.BadInput;

/// <summary>
/// Scene inputs that cannot be checked in as corpus files: one too big to keep in the repository (written at
/// test time, still a file the commands read), files that do not exist, and files that exist but cannot be read.
/// </summary>
[Collection(BadInputCollection.Name)]
public sealed class BadSceneInputTests : IDisposable
{
    private readonly ScratchDirectory _input = new("qrt-bad-input-");
    private readonly ScratchDirectory _output = new("qrt-bad-input-out-");

    public void Dispose()
    {
        _input.Dispose();
        _output.Dispose();
    }

    private string Output => _output.File("out.png");

    /// <summary>render, scenes check and supersample each refuse <paramref name="scene"/> the same way.</summary>
    private void AssertRefusedEverywhere(string scene, string element, string problem)
    {
        Outcome.Of("render", scene, "-e", "classical", "--size", "4", "-o", Output).AssertBadInput(scene, element, problem, _output.Path);
        Outcome.Of("scenes", "check", scene).AssertBadInput(scene, element, problem, null);
        Outcome.Of("supersample", "--scene", scene, "--size", "2", "--subpixels", "2", "-m", "mc", "-o", Output)
            .AssertBadInput(scene, element, problem, _output.Path);
    }

    /// <summary>
    /// 100,000 valid rectangles (about 6 MB): far past the 4096 the index register and lookup tables are built
    /// for, so the loader refuses the count instead of starting a render that could never finish.
    /// </summary>
    [Fact]
    public void HundredThousandPrimitives()
    {
        const int count = 100_000;
        var text = new StringBuilder("""
            {
              "image": { "width": 8, "height": 8 },
              "grid": { "integerBits": 4 },
              "camera": { "position": [4, 4, 1], "lookAt": [4, 4, 8] },
              "materials": { "white": { "diffuse": [0.8, 0.8, 0.8] } },
              "rectangles": [
            """);
        for (var k = 0; k < count; k++)
        {
            // Unit squares facing the camera, stacked on the 4-bit grid: each one valid on its own.
            var (x, y, z) = (k % 15, k / 15 % 15, 2 + k / 225 % 13);
            text.Append(k == 0 ? "\n" : ",\n").Append($"    {{ \"min\": [{x}, {y}, {z}], \"max\": [{x + 1}, {y + 1}, {z}], \"material\": \"white\" }}");
        }
        text.Append("\n  ]\n}\n");
        var scene = _input.File("hundred-thousand-primitives.json");
        File.WriteAllText(scene, text.ToString());
        AssertRefusedEverywhere(scene, "rectangles", $"{count} rectangles; at most 4096");
    }

    [Fact]
    public void MissingFile() =>
        AssertRefusedEverywhere(_input.File("no-such-scene.json"), "file", "not found");

    [Fact]
    public void FileInAMissingDirectory() =>
        AssertRefusedEverywhere(Path.Combine(_input.Path, "no-such-directory", "scene.json"), "file", "not found");

    /// <summary>A directory where a file belongs: opening it fails on every system, for every user.</summary>
    [Fact]
    public void DirectoryInsteadOfAFile() =>
        AssertRefusedEverywhere(_input.Path, "file", "is a directory");

    /// <summary>
    /// An unreadable file. The tests run as root, and root reads a file whatever its mode (chmod 000 stops
    /// nobody), so this uses a file whose read fails for root too: /proc/self/mem opens, but reading it from
    /// offset 0 reads the process's unmapped address 0 and the kernel answers EIO.
    /// </summary>
    [LinuxFact("/proc/self/mem, whose read fails for root too")]
    public void FileWhoseReadFails()
    {
        AssertRefusedEverywhere("/proc/self/mem", "file", "cannot be read");
    }

    /// <summary>
    /// A file without read permission, for root too (chmod 000 stops nobody as root): a bus's uevent file in
    /// sysfs is write-only, and the kernel answers EACCES to any read.
    /// </summary>
    [LinuxFact("sysfs, whose uevent files refuse reads to root too")]
    public void FileWithoutReadPermission()
    {
        AssertRefusedEverywhere("/sys/bus/platform/uevent", "file", "cannot be read (Access to the path");
    }
}
