using QuantumRayTracing.Experiments;
using QuantumRayTracing.Tests.Cli;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Tests.Experiments;

/// <summary>`bench lights` on tiny images: the report, its six images, and the files it must not replace.</summary>
public sealed class BenchLightsCommandTests : IDisposable
{
    private readonly ScratchDirectory _scratch = new("qrt-bench-lights-");

    public void Dispose() => _scratch.Dispose();

    private string[] Run(string report) =>
        ["bench", "lights", "--scenes", RepositoryPaths.Scenes, "--size", "4", "--image-size", "3", "--reference-samples", "2", "-o", Path.Combine(_scratch.Path, report)];

    [Fact]
    public void WritesTheReportAndItsImages()
    {
        Assert.Equal(0, ConsoleCapture.Run(Run("lights.md")).Code);
        var text = File.ReadAllText(Path.Combine(_scratch.Path, "lights.md"));
        Assert.StartsWith(GeneratedReport.MarkdownMarker(BenchLightsCommand.CommandText), text);
        Assert.Contains("paper: 21.8 Int/Ray against 64.0", text);
        Assert.Contains("paper: 22.4 Int/Ray against 32.0", text);
        var images = Directory.GetFiles(_scratch.Path, "*.png").Select(Path.GetFileName).Order().ToArray();
        Assert.Equal(6, images.Length);
        Assert.All(images, name => Assert.Contains($"]({name})", text));
        Assert.All(images, name => Assert.True(PngWriter.IsWrittenHere(Path.Combine(_scratch.Path, name!))));
        // A second run replaces its own files.
        Assert.Equal(0, ConsoleCapture.Run(Run("lights.md")).Code);
    }

    [Fact]
    public void AForeignImageStopsTheRunBeforeAnyWork()
    {
        var foreign = Path.Combine(_scratch.Path, "lights-area-quantum.png");
        File.WriteAllText(foreign, "someone else's");
        Assert.Equal(ExitCodes.BadInput, ConsoleCapture.Run(Run("lights.md")).Code);
        Assert.Equal("someone else's", File.ReadAllText(foreign));
        Assert.False(File.Exists(Path.Combine(_scratch.Path, "lights.md")));
    }
}
