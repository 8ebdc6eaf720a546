using QuantumRayTracing.Output;

namespace QuantumRayTracing.Tests.Output;

public sealed class ImageFilesTests : IDisposable
{
    private readonly ScratchDirectory _scratch = new("qrt-image-files-");

    [Fact]
    public void ImagesOfOneCommandAreWrittenAllOrNone()
    {
        var image = new RgbImage(2, 2);
        // The second target's directory refuses new files even for root, after the first was already encoded and placed.
        var refused = Path.Combine("/proc/self", "qrt-second.png");

        var error = Assert.Throws<UserError>(() => ImageFiles.Write([(image, _scratch.File("first.png")), (image, refused)]));

        Assert.Contains("cannot be written", error.Message);
        Assert.Empty(Directory.EnumerateFileSystemEntries(_scratch.Path));
    }

    [Fact]
    public void AllImagesAreWrittenWhenEveryTargetAcceptsThem()
    {
        var image = new RgbImage(2, 2);

        ImageFiles.Write([(image, _scratch.File("a.png")), (image, _scratch.File("b.png"))]);

        Assert.Equal(["a.png", "b.png"], Directory.EnumerateFiles(_scratch.Path).Select(Path.GetFileName).Order());
        Assert.True(PngWriter.IsWrittenHere(_scratch.File("b.png")));
    }

    public void Dispose() => _scratch.Dispose();
}
