namespace QuantumRayTracing.Tests.BadInput;

/// <summary>
/// Every file in BadInput/Images (but the baseline valid.png, a 4x4 RGB image) through `supersample --image`.
/// BadInput/README.md says how each file is damaged. A PNG's errors name the file and then the part of it at
/// fault (the signature, a chunk, a header field), so each case gives a phrase naming that part.
/// </summary>
[Collection(BadInputCollection.Name)]
public sealed class BadImageFileTests : IDisposable
{
    private readonly ScratchDirectory _output = new("qrt-bad-image-");

    public void Dispose() => _output.Dispose();

    /// <summary>File → phrase naming the part at fault and the problem.</summary>
    public static TheoryData<string, string> Cases => new()
    {
        { "not-a-png.png", "does not start with the PNG signature" },
        { "empty.png", "does not start with the PNG signature" },
        { "truncated.png", "truncated: the IDAT chunk" },
        { "bad-crc.png", "bad CRC in the IHDR chunk" },
        { "zero-width.png", "size 0x4; both sides must be at least 1" },
        { "million-wide.png", "too large (1000000x4" },
        { "colour-type-5.png", "unsupported colour type 5" },
        { "sixteen-bit.png", "16-bit channels are not supported" },
        { "interlaced.png", "interlaced (Adam7) PNGs are not supported" },
        { "no-image-data.png", "no image data (IDAT chunk)" },
        { "damaged-zlib.png", "not a valid zlib stream" },
        { "short-image-data.png", "truncated: the image data holds 26 of the 52 bytes" },
        { "palette-without-plte.png", "without a PLTE chunk" },
        // A valid PNG the command cannot use: 3x3 pixels do not split into 2x2 subpixel blocks.
        { "odd-size.png", "not a multiple of --subpixels 2" },
    };

    private string Output => _output.File("out.png");

    private void AssertRefused(string image, string problem) =>
        Outcome.Of("supersample", "--image", image, "--subpixels", "2", "-m", "mc", "-o", Output)
            .AssertBadInput(image, "", problem, _output.Path);

    [Theory]
    [MemberData(nameof(Cases))]
    public void SupersampleRefuses(string file, string problem) => AssertRefused(Corpus.Image(file), problem);

    [Fact]
    public void EveryCorpusFileIsACase() =>
        Assert.Equal(Corpus.Files("Images", "valid.png"), Cases.Select(c => (string)c[0]).Order());

    [Fact]
    public void MissingImage() => AssertRefused(_output.File("no-such-image.png"), "no such file");

    /// <summary>A directory given as the image (a scratch directory of its own, so the output directory stays empty).</summary>
    [Fact]
    public void DirectoryInsteadOfAnImage()
    {
        using var directory = new ScratchDirectory("qrt-bad-image-dir-");
        AssertRefused(directory.Path, "cannot be read");
    }

    /// <summary>An image whose read fails even for root: see <see cref="BadSceneInputTests.FileWhoseReadFails"/>.</summary>
    [Fact]
    public void ImageWhoseReadFails()
    {
        if (!OperatingSystem.IsLinux()) return;
        AssertRefused("/proc/self/mem", "cannot be read");
    }

    [Fact]
    public void BaselineSupersamples()
    {
        var outcome = Outcome.Of("supersample", "--image", Corpus.Image("valid.png"), "--subpixels", "2", "-m", "mc", "-o", Output);
        Assert.True(outcome.Code == 0, outcome.Error);
        Assert.Equal(["out.png"], Directory.GetFiles(_output.Path).Select(Path.GetFileName));
    }
}
