namespace QuantumRayTracing.Tests.BadInput;

/// <summary>
/// Every file in BadInput/Images (but the baseline valid.png, a 4x4 RGB image) through `supersample --image`.
/// BadInput/README.md says how each file is damaged. Each error names the file and then what is wrong: the header,
/// the image data, the declared size or the file's end, so each case gives a phrase naming that.
/// </summary>
[Collection(BadInputCollection.Name)]
public sealed class BadImageFileTests : IDisposable
{
    private readonly ScratchDirectory _output = new("qrt-bad-image-");

    public void Dispose() => _output.Dispose();

    /// <summary>File → phrase naming the part at fault and the problem.</summary>
    public static TheoryData<string, string> Cases => new()
    {
        // Text that starts like a GIF, whose header then reads as 8250x26740 pixels: the size guard refuses it before decoding.
        { "not-a-png.png", "the image is too large (8250x26740" },
        { "empty.png", "the file is empty" },
        { "truncated.png", "truncated: the PNG file ends before its IEND chunk" },
        { "bad-crc.png", "damaged: the PNG header cannot be read" },
        { "zero-width.png", "damaged: the PNG header cannot be read" },
        { "million-wide.png", "too large (1000000x4" },
        { "colour-type-5.png", "damaged: the PNG header cannot be read" },
        { "interlaced.png", "the PNG image data cannot be decoded" },
        { "no-image-data.png", "damaged: the PNG header cannot be read" },
        { "damaged-zlib.png", "the PNG image data cannot be decoded" },
        { "short-image-data.png", "the PNG image data cannot be decoded" },
        { "palette-without-plte.png", "the PNG image data cannot be decoded" },
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
    [LinuxFact("/proc/self/mem, whose read fails for root too")]
    public void ImageWhoseReadFails()
    {
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
