using QuantumRayTracing.Output;
using SkiaSharp;

namespace QuantumRayTracing.Tests.Output;

public sealed class PngWriterTests : IDisposable
{
    private readonly ScratchDirectory _scratch = new("qrt-png-writer-");

    public void Dispose() => _scratch.Dispose();

    private static RgbImage Gradient(int width, int height) =>
        RgbImage.FromLinear(width, height, (x, y) => (x / (width - 1.0), y / (height - 1.0), (x + y) % 3 / 2.0));

    [Fact]
    public void DecodesToTheSamePixels()
    {
        var image = Gradient(37, 23);
        var decoded = ImageReader.Decode(PngWriter.Encode(image), "gradient.png");
        Assert.Equal(image.Pixels.ToArray(), decoded.Pixels.ToArray());
    }

    [Fact]
    public void TheSameImageGivesTheSameBytes() =>
        Assert.Equal(PngWriter.Encode(Gradient(64, 48)), PngWriter.Encode(Gradient(64, 48)));

    [Fact]
    public void OnlyFilesWrittenHereCarryTheMark()
    {
        var ours = _scratch.File("ours.png");
        PngWriter.Write(Gradient(4, 4), ours);
        // The same pixels encoded by SkiaSharp alone, as another program would: a valid PNG without the mark.
        var theirs = _scratch.File("theirs.png");
        using (var bitmap = new SKBitmap(4, 4))
        using (var data = bitmap.Encode(SKEncodedImageFormat.Png, 100))
            File.WriteAllBytes(theirs, data.ToArray());
        var text = _scratch.File("text.png");
        File.WriteAllText(text, $"Software\0{PngWriter.Software}");

        Assert.True(PngWriter.IsWrittenHere(ours));
        Assert.False(PngWriter.IsWrittenHere(theirs));
        Assert.False(PngWriter.IsWrittenHere(text));
    }
}
