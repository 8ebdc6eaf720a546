using QuantumRayTracing.Cli;
using QuantumRayTracing.Output;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Output;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Cli;

/// <summary>`render` through <see cref="CommandLine.Run"/>: exit codes (0 ok, 1 usage, 2 bad input) and the files it writes or refuses to write.</summary>
public sealed class RenderCommandTests : IDisposable
{
    private static readonly string Scene = Path.Combine(RepositoryPaths.Scenes, "qornell-8.json");

    private readonly ScratchDirectory _scratch = new("qrt-render-");

    public void Dispose() => _scratch.Dispose();

    private static RgbImage Classical(int size)
    {
        using var search = new ClassicalHitSearch();
        return SceneRenderer.Render(Load("qornell-8.json"), search, new RenderOptions(size, size)).Image;
    }

    [Fact]
    public void ClassicalRenderWritesAnImageOfTheRequestedSize()
    {
        var output = _scratch.File("x.png");
        Assert.Equal(0, ConsoleCapture.Run(["render", Scene, "--engine", "classical", "--size", "8", "-o", output]).Code);
        var image = ImageReader.Read(output);
        Assert.Equal((8, 8), (image.Width, image.Height));
        Assert.True(image.Pixels.SequenceEqual(Classical(8).Pixels));
        Assert.Equal(["x.png"], _scratch.FileNames());
    }

    [Fact]
    public void NonSquareSize()
    {
        var output = _scratch.File("wide.png");
        Assert.Equal(0, ConsoleCapture.Run(["render", Scene, "-e", "classical", "--size", "6x3", "-o", output]).Code);
        Assert.Equal((6, 3), (ImageReader.Read(output).Width, ImageReader.Read(output).Height));
    }

    [Fact]
    public void ClassicalImageIsTheReference()
    {
        var output = _scratch.File("c.png");
        Assert.Equal(0, ConsoleCapture.Run(["render", Scene, "-e", "classical", "--size", "8", "--reference", "-o", output]).Code);
        Assert.Equal(["c-difference.png", "c-reference.png", "c.png"], _scratch.FileNames());
        Assert.Equal(File.ReadAllBytes(output), File.ReadAllBytes(_scratch.File("c-reference.png")));
        var difference = ImageReader.Read(_scratch.File("c-difference.png"));
        var reference = ImageReader.Read(output);
        for (var y = 0; y < 8; y++)
            for (var x = 0; x < 8; x++)
            {
                var (r, g, b) = reference.GetPixel(x, y);
                Assert.Equal(((byte)(r / 4), (byte)(g / 4), (byte)(b / 4)), difference.GetPixel(x, y));
            }
    }

    [Fact]
    public void ReferenceAndDifferenceImagesOfAQuantumRender()
    {
        // One pass and one shadow round on the analytic engine, without the neighbour tricks or the budget, leave wrong pixels to mark.
        var output = _scratch.File("q.png");
        Assert.Equal(0, ConsoleCapture.Run(["render", Scene, "-e", "analytic", "--seed", "3", "--size", "12", "--passes", "1", "--shadow-passes", "1",
            "--neighbours", "false", "--shadow-neighbours", "false", "--stop", "off", "--lattice", "0", "--budget", "0", "--reference", "-o", output]).Code);
        var image = ImageReader.Read(output);
        var reference = ImageReader.Read(_scratch.File("q-reference.png"));
        var difference = ImageReader.Read(_scratch.File("q-difference.png"));
        Assert.True(reference.Pixels.SequenceEqual(Classical(12).Pixels));
        var wrong = 0;
        for (var y = 0; y < 12; y++)
            for (var x = 0; x < 12; x++)
            {
                var differs = image.GetPixel(x, y) != reference.GetPixel(x, y);
                wrong += differs ? 1 : 0;
                // A reference pixel / 4 is at most 63, so pure red marks a difference and nothing else.
                Assert.Equal(differs, difference.GetPixel(x, y) == (255, 0, 0));
            }
        Assert.True(wrong > 0);
    }

    [Fact]
    public void PrintsTheExpectedAndTheMeasuredShareOfWrongPixels()
    {
        // A process of its own: Spectre.Console keeps the first writer it found, so an in-process run's table is not captured.
        var (code, output, _) = QrtProcess.Run(new Dictionary<string, string>(), _scratch.Path, "render", Scene, "--size", "8", "-o", _scratch.File("b.png"));
        Assert.Equal(0, code);
        var lines = output.Split('\n').Select(l => l.TrimEnd('\r')).ToArray();
        var line = lines.Single(l => l.StartsWith("wrong pixels: expected ", StringComparison.Ordinal));
        Assert.Contains("measured 0 (0.000 %); budget 0.1 %", line);
        Assert.Contains(lines, l => l.StartsWith("(expected: an expectation", StringComparison.Ordinal));
    }

    [Fact]
    public void OwnPngIsReplaced()
    {
        var output = _scratch.File("x.png");
        PngWriter.Write(new RgbImage(2, 2), output);
        Assert.Equal(0, ConsoleCapture.Run(["render", Scene, "-e", "classical", "--size", "8", "-o", output]).Code);
        Assert.Equal(8, ImageReader.Read(output).Width);
    }

    [Fact]
    public void MissingDirectoryIsRefusedBeforeRendering()
    {
        var output = Path.Combine(_scratch.Path, "missing", "x.png");
        Assert.Equal(ExitCodes.BadInput, ConsoleCapture.Run(["render", Scene, "-e", "classical", "--size", "8", "-o", output]).Code);
        Assert.False(Directory.Exists(Path.Combine(_scratch.Path, "missing")));
        Assert.Empty(_scratch.FileNames());
    }

    [Theory]
    [InlineData(new byte[] { 110, 111, 116, 32, 111, 117, 114, 115 })]                  // "not ours"
    [InlineData(new byte[] { 0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A, 0, 0, 0, 13 })] // a PNG start without our marker
    public void ForeignFileIsNotOverwritten(byte[] content)
    {
        var output = _scratch.File("x.png");
        File.WriteAllBytes(output, content);
        Assert.Equal(ExitCodes.BadInput, ConsoleCapture.Run(["render", Scene, "-e", "classical", "--size", "8", "-o", output]).Code);
        Assert.Equal(content, File.ReadAllBytes(output));
        Assert.Equal(["x.png"], _scratch.FileNames());
    }

    [Fact]
    public void ForeignFileAtASiblingOutputStopsEveryOutput()
    {
        var difference = _scratch.File("x-difference.png");
        File.WriteAllText(difference, "someone else's");
        Assert.Equal(ExitCodes.BadInput, ConsoleCapture.Run(["render", Scene, "-e", "classical", "--size", "8", "--reference", "-o", _scratch.File("x.png")]).Code);
        Assert.Equal("someone else's", File.ReadAllText(difference));
        Assert.Equal(["x-difference.png"], _scratch.FileNames());
    }

    [Fact]
    public void OutputOverTheInputSceneIsRefused()
    {
        var scene = _scratch.File("scene.json");
        File.Copy(Scene, scene);
        var before = File.ReadAllBytes(scene);
        Assert.Equal(ExitCodes.BadInput, ConsoleCapture.Run(["render", scene, "-e", "classical", "--size", "8", "-o", scene]).Code);
        Assert.Equal(before, File.ReadAllBytes(scene));
        Assert.Equal(["scene.json"], _scratch.FileNames());
    }

    [Theory]
    [InlineData("--size", "0")]
    [InlineData("--size", "3x")]
    [InlineData("--size", "x3")]
    [InlineData("--size", "8193")]
    [InlineData("--passes", "0")]
    [InlineData("--passes", "65")]
    [InlineData("--shadow-passes", "0")]
    [InlineData("--engine", "bogus")]
    [InlineData("--growth", "2")]
    [InlineData("--lattice", "7")]
    [InlineData("--lattice", "-1")]
    public void UsageErrorsExitWithOne(string option, string value)
    {
        Assert.Equal(1, ConsoleCapture.Run(["render", Scene, "-e", "classical", option, value, "-o", _scratch.File("x.png")]).Code);
        Assert.Empty(_scratch.FileNames());
    }

    [Fact]
    public void SceneWithAnErrorExitsWithTwoAndWritesNothing()
    {
        // x = 40 is off the 5-bit grid 0..31.
        var scene = _scratch.File("bad.json");
        File.WriteAllText(scene, File.ReadAllText(Scene).Replace("\"max\": [16, 0, 30]", "\"max\": [40, 0, 30]"));
        Assert.NotEqual(File.ReadAllText(Scene), File.ReadAllText(scene));
        Assert.Equal(ExitCodes.BadInput, ConsoleCapture.Run(["render", scene, "-e", "classical", "--size", "8", "--reference", "-o", _scratch.File("x.png")]).Code);
        Assert.Equal(["bad.json"], _scratch.FileNames());
    }

    [Fact]
    public void MissingSceneExitsWithTwo()
    {
        Assert.Equal(ExitCodes.BadInput, ConsoleCapture.Run(["render", _scratch.File("nowhere.json"), "-e", "classical", "-o", _scratch.File("x.png")]).Code);
        Assert.Empty(_scratch.FileNames());
    }
}
