using QuantumRayTracing.Output;
using QuantumRayTracing.Tests.Engines;
using QuantumRayTracing.Tests.Output;

namespace QuantumRayTracing.Tests.Cli;

/// <summary>`supersample --engine fullstate` end to end on inputs whose outcomes are certain, so one run decides.</summary>
public sealed class SupersampleFullStateTests : IDisposable
{
    private readonly ScratchDirectory _scratch = new("qrt-supersample-fullstate-");

    public void Dispose() => _scratch.Dispose();

    [Theory]
    [InlineData("qss", "--planes", "1")]
    [InlineData("mlae", "--queries", "20")]
    public void BlackAndWhiteBlocksComeOutExactOnTheSimulator(string method, params string[] extra)
    {
        // Means of 0 and 1 are read with certainty by every circuit: no statistics needed.
        var image = new RgbImage(4, 2);
        for (var y = 0; y < 2; y++)
            for (var x = 0; x < 4; x++)
                image.SetPixel(x, y, x < 2 ? (byte)255 : (byte)0, 0, x >= 2 ? (byte)255 : (byte)0);
        var input = Path.Combine(_scratch.Path, "in.png");
        var output = Path.Combine(_scratch.Path, "out.png");
        PngWriter.Write(image, input);
        var (code, error) = ConsoleCapture.Run(["supersample", "--image", input, "--subpixels", "2", "-m", method, .. extra, "-e", "fullstate", "--workers", "1", "-o", output]);
        Assert.True(code == 0, error);
        var result = ImageReader.Read(output);
        Assert.Equal(((byte)255, (byte)0, (byte)0), result.GetPixel(0, 0));
        Assert.Equal(((byte)0, (byte)0, (byte)255), result.GetPixel(1, 0));
    }
}
