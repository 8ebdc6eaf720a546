using System.Buffers.Binary;
using System.IO.Hashing;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Tests.Output;

/// <summary>
/// <see cref="ImageReader"/> on files written by another program (ImageMagick, Output/Images/make-fixtures.sh), checked
/// against the pixel values of the text sources they were made from.
/// </summary>
public sealed class ImageReaderTests
{
    /// <summary>
    /// File → largest difference allowed from the source, in 8-bit levels. The 8-bit files hold the high byte of each
    /// 16-bit source sample (how ImageMagick 6 reduces depth; `convert FILE txt:-` shows it), so they are compared with
    /// that, losslessly: no difference. The 16-bit file is compared with the sample scaled to 0..255 and rounded, within
    /// one level, since the PNG spec allows a decoder to shift rather than scale (the low bytes of 8191 x are 0xFF, 0xFE,
    /// ...: a decoder that read them would be far off). JPEG at quality 95 without chroma subsampling: 6 levels (4 measured
    /// here on these smooth ramps, the rest room for another JPEG library's rounding), while a wrong channel order or colour conversion (tens of
    /// levels) still fails.
    /// </summary>
    public static TheoryData<string, int> Levels => new()
    {
        { "levels-16bit.png", 1 },
        { "levels-interlaced.png", 0 },
        { "levels-palette.png", 0 },
        { "levels.webp", 0 },
        { "levels.bmp", 0 },
        { "levels.gif", 0 },
        { "levels.jpg", 6 },
    };

    private static int Expected(int sample, bool sixteenBit) => sixteenBit ? ImageFixtures.To8Bit(sample, 65535) : sample >> 8;

    [Theory]
    [MemberData(nameof(Levels))]
    public void DecodesTheSourcePixels(string file, int tolerance)
    {
        var (source, _) = ImageFixtures.Source("levels.ppm");
        var sixteenBit = file.Contains("16bit");
        var image = ImageReader.Read(ImageFixtures.Path(file));
        Assert.Equal((source.GetLength(0), source.GetLength(1)), (image.Width, image.Height));
        var worst = 0;
        for (var y = 0; y < image.Height; y++)
            for (var x = 0; x < image.Width; x++)
            {
                var (r, g, b) = image.GetPixel(x, y);
                var (er, eg, eb) = source[x, y];
                worst = new[] { worst, Math.Abs(r - Expected(er, sixteenBit)), Math.Abs(g - Expected(eg, sixteenBit)), Math.Abs(b - Expected(eb, sixteenBit)) }.Max();
            }
        Assert.True(worst <= tolerance, $"{file}: a channel is {worst} levels from the source (at most {tolerance} allowed)");
    }

    [Fact]
    public void TransparencyIsCompositedOverBlack()
    {
        // levels-alpha.png is the 8-bit source at alpha 128/255; over black each channel is v 128 / 255 (one level for rounding).
        var (source, _) = ImageFixtures.Source("levels.ppm");
        var image = ImageReader.Read(ImageFixtures.Path("levels-alpha.png"));
        for (var y = 0; y < image.Height; y++)
            for (var x = 0; x < image.Width; x++)
            {
                var (er, eg, eb) = source[x, y];
                int[] expected = [.. new[] { er, eg, eb }.Select(v => Expected(v, sixteenBit: false) * 128 / 255.0).Select(v => (int)Math.Round(v))];
                var (r, g, b) = image.GetPixel(x, y);
                Assert.True(Math.Abs(r - expected[0]) <= 1 && Math.Abs(g - expected[1]) <= 1 && Math.Abs(b - expected[2]) <= 1,
                    $"({x}, {y}) is ({r}, {g}, {b}), expected about ({expected[0]}, {expected[1]}, {expected[2]})");
            }
    }

    [Fact]
    public void RefusesADeclaredSizeAboveTheLimitBeforeDecoding()
    {
        // A PNG whose header claims 40000x2 pixels (its CRC made right again): refused on the header alone, so the
        // pixels need not even be there.
        var png = PngWriter.Encode(new RgbImage(1, 2));
        BinaryPrimitives.WriteUInt32BigEndian(png.AsSpan(16), 40000);
        BinaryPrimitives.WriteUInt32BigEndian(png.AsSpan(29), Crc32.HashToUInt32(png.AsSpan(12, 17)));
        var error = Assert.Throws<UserError>(() => ImageReader.Decode(png, "big.png"));
        Assert.StartsWith("big.png: the image is too large (40000x2", error.Message);
    }
}
