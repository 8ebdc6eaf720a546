using QuantumRayTracing.Output;
using static QuantumRayTracing.Tests.Output.HandMadePng;

namespace QuantumRayTracing.Tests.Output;

/// <summary>
/// The host's PNG decoder: round trips with the encoder, hand-made files of every colour type and bit depth with
/// every filter type (expected colours worked out in the test from the PNG spec), and damaged files, each of which
/// must give one <see cref="UserError"/> naming the file and the problem.
/// </summary>
public sealed class PngDecoderTests : IDisposable
{
    private const string Name = "in.png";

    private readonly ScratchDirectory _scratch = new("qrt-png-decoder-");

    public void Dispose() => _scratch.Dispose();

    [Theory]
    [InlineData(1, 1)]
    [InlineData(2, 1)]
    [InlineData(1, 7)]
    [InlineData(37, 23)]
    [InlineData(130, 3)]
    public void RoundTripsTheEncoder(int width, int height)
    {
        var random = new Random(width * 1000 + height);
        var image = new RgbImage(width, height);
        for (var y = 0; y < height; y++)
            for (var x = 0; x < width; x++)
                image.SetPixel(x, y, (byte)random.Next(256), (byte)random.Next(256), (byte)(x * 7 + y));
        var decoded = PngDecoder.Decode(PngEncoder.Encode(image), Name);
        Assert.Equal((width, height), (decoded.Width, decoded.Height));
        Assert.Equal(image.Pixels.ToArray(), decoded.Pixels.ToArray());
    }

    [Fact]
    public void ReadsAFileWrittenByTheEncoder()
    {
        var path = Path.Combine(_scratch.Path, "x.png");
        var image = RgbImage.FromLinear(9, 4, (x, y) => (x / 8.0, y / 3.0, 0.5));
        PngEncoder.Write(image, path);
        Assert.Equal(image.Pixels.ToArray(), PngDecoder.Read(path).Pixels.ToArray());
    }

    public static TheoryData<int, int> ColourTypes => new()
    {
        { 0, 1 }, { 0, 2 }, { 0, 4 }, { 0, 8 }, { 2, 8 }, { 3, 1 }, { 3, 2 }, { 3, 4 }, { 3, 8 }, { 4, 8 }, { 6, 8 },
    };

    [Theory]
    [MemberData(nameof(ColourTypes))]
    public void ReadsEveryColourTypeWithEveryFilter(int colour, int depth)
    {
        // 7 pixels wide, so rows of sub-byte samples end in padding; row y uses filter y mod 5, twice each.
        const int width = 7, height = 10;
        var random = new Random(colour * 100 + depth);
        var channels = colour switch { 2 => 3, 4 => 2, 6 => 4, _ => 1 };
        var rows = Enumerable.Range(0, height)
            .Select(_ => Enumerable.Range(0, width * channels).Select(_ => random.Next(1 << depth)).ToArray()).ToArray();
        var palette = Enumerable.Range(0, 3 * (1 << depth)).Select(_ => (byte)random.Next(256)).ToArray();
        var png = Image(width, depth, colour, rows, y => y % 5, colour == 3 ? [Chunk("PLTE", palette)] : []);

        var decoded = PngDecoder.Decode(png, Name);

        Assert.Equal((width, height), (decoded.Width, decoded.Height));
        for (var y = 0; y < height; y++)
            for (var x = 0; x < width; x++)
            {
                var s = rows[y].AsSpan(x * channels, channels).ToArray();
                (int, int, int) expected = colour switch
                {
                    0 => (Grey(s[0], depth), Grey(s[0], depth), Grey(s[0], depth)),
                    2 => (s[0], s[1], s[2]),
                    3 => (palette[3 * s[0]], palette[3 * s[0] + 1], palette[3 * s[0] + 2]),
                    4 => (OverBlack(s[0], s[1]), OverBlack(s[0], s[1]), OverBlack(s[0], s[1])),
                    _ => (OverBlack(s[0], s[3]), OverBlack(s[1], s[3]), OverBlack(s[2], s[3])),
                };
                var (r, g, b) = decoded.GetPixel(x, y);
                Assert.True(expected == (r, g, b), $"pixel ({x}, {y}): expected {expected}, got {(r, g, b)}");
            }
    }

    [Fact]
    public void UndoesEachFilterTypeOnKnownBytes()
    {
        // 8-bit grey, 3 pixels, one row per filter type; filtered bytes worked out by hand from the PNG spec, section 9.2.
        byte[] scanlines =
        [
            1, 10, 5, 250, // Sub:     10, 15, (15 + 250) mod 256 = 9
            2, 1, 2, 3,    // Up:      11, 17, 12
            3, 4, 4, 4,    // Average: 4 + 11/2 = 9, 4 + (9 + 17)/2 = 17, 4 + (17 + 12)/2 = 18
            4, 1, 1, 1,    // Paeth:   predicts b = 9, b = 17, then a = 18 on the pa = pb tie: 10, 18, 19
            0, 7, 8, 9,    // None
        ];
        var png = File(Chunk("IHDR", Header(3, 5, 8, 0)), Chunk("IDAT", Deflate(scanlines)), Chunk("IEND", []));
        var decoded = PngDecoder.Decode(png, Name);
        int[,] expected = { { 10, 15, 9 }, { 11, 17, 12 }, { 9, 17, 18 }, { 10, 18, 19 }, { 7, 8, 9 } };
        for (var y = 0; y < 5; y++)
            for (var x = 0; x < 3; x++)
                Assert.Equal(((byte)expected[y, x], (byte)expected[y, x], (byte)expected[y, x]), decoded.GetPixel(x, y));
    }

    [Fact]
    public void PaletteTransparencyIsCompositedOverBlack()
    {
        // Three entries, tRNS for the first two only: the third stays opaque.
        byte[] palette = [200, 100, 50, 10, 20, 30, 255, 255, 255];
        var png = Image(3, 8, 3, [[0, 1, 2]], _ => 0, Chunk("PLTE", palette), Chunk("tRNS", [128, 0]));
        var decoded = PngDecoder.Decode(png, Name);
        // 200·128/255 = 100.4, 100·128/255 = 50.2, 50·128/255 = 25.1.
        Assert.Equal(((byte)100, (byte)50, (byte)25), decoded.GetPixel(0, 0));
        Assert.Equal(((byte)0, (byte)0, (byte)0), decoded.GetPixel(1, 0));
        Assert.Equal(((byte)255, (byte)255, (byte)255), decoded.GetPixel(2, 0));
    }

    [Fact]
    public void ColourKeysMakePixelsBlack()
    {
        var grey = Image(3, 4, 0, [[5, 6, 15]], _ => 0, Chunk("tRNS", [0, 6]));
        var greyDecoded = PngDecoder.Decode(grey, Name);
        Assert.Equal([85, 0, 255], Enumerable.Range(0, 3).Select(x => (int)greyDecoded.GetPixel(x, 0).R));

        var rgb = Image(2, 8, 2, [[1, 2, 3, 1, 2, 4]], _ => 0, Chunk("tRNS", [0, 1, 0, 2, 0, 3]));
        var rgbDecoded = PngDecoder.Decode(rgb, Name);
        Assert.Equal(((byte)0, (byte)0, (byte)0), rgbDecoded.GetPixel(0, 0));
        Assert.Equal(((byte)1, (byte)2, (byte)4), rgbDecoded.GetPixel(1, 0));
    }

    [Fact]
    public void SplitImageDataAndAncillaryChunksAreRead()
    {
        byte[] raw = [0, 1, 2, 3, 0, 4, 5, 6];
        var compressed = Deflate(raw);
        var png = File(Chunk("IHDR", Header(1, 2, 8, 2)), Chunk("tEXt", "Comment\0hi"u8.ToArray()), Chunk("abCd", [1, 2]),
            Chunk("IDAT", compressed[..3]), Chunk("IDAT", []), Chunk("IDAT", compressed[3..]), Chunk("zzZz", []), Chunk("IEND", []));
        var decoded = PngDecoder.Decode(png, Name);
        Assert.Equal(((byte)1, (byte)2, (byte)3), decoded.GetPixel(0, 0));
        Assert.Equal(((byte)4, (byte)5, (byte)6), decoded.GetPixel(0, 1));
    }

    public static TheoryData<string, byte[], string> DamagedFiles()
    {
        var idat = Chunk("IDAT", Deflate([0, 9, 9, 9]));
        var ihdr = Chunk("IHDR", Header(1, 1, 8, 2));
        var iend = Chunk("IEND", []);
        var good = File(ihdr, idat, iend);
        var badCrc = good.ToArray();
        badCrc[8 + ihdr.Length + 9] ^= 0x40; // a byte of the IDAT data
        var data = new TheoryData<string, byte[], string>
        {
            { "text", "hello, world"u8.ToArray(), "not a PNG" },
            { "empty", [], "not a PNG" },
            { "signature only", Signature, "truncated" },
            { "no IEND", File(ihdr, idat), "truncated" },
            { "bad CRC", badCrc, "bad CRC in the IDAT chunk" },
            { "16-bit RGB", File(Chunk("IHDR", Header(1, 1, 16, 2)), idat, iend), "16-bit" },
            { "16-bit grey", File(Chunk("IHDR", Header(1, 1, 16, 0)), idat, iend), "16-bit" },
            { "interlaced", File(Chunk("IHDR", Header(1, 1, 8, 2, interlace: 1)), idat, iend), "interlaced" },
            { "colour type 5", File(Chunk("IHDR", Header(1, 1, 8, 5)), idat, iend), "colour type 5" },
            { "RGB with 4 bits", File(Chunk("IHDR", Header(1, 1, 4, 2)), idat, iend), "bit depth 4" },
            { "width 0", File(Chunk("IHDR", Header(0, 1, 8, 2)), idat, iend), "size 0x1" },
            { "height 0", File(Chunk("IHDR", Header(1, 0, 8, 2)), idat, iend), "size 1x0" },
            { "too wide", File(Chunk("IHDR", Header(40000, 1, 8, 2)), idat, iend), "too large" },
            { "too many pixels", File(Chunk("IHDR", Header(16384, 16384, 8, 2)), idat, iend), "too large" },
            { "width 2^32 - 1", File(Chunk("IHDR", Header(uint.MaxValue, 1, 8, 2)), idat, iend), "too large" },
            { "short IHDR", File(Chunk("IHDR", [0, 0, 0, 1]), idat, iend), "IHDR" },
            { "IDAT first", File(idat, ihdr, iend), "first chunk is IDAT" },
            { "no IDAT", File(ihdr, iend), "no image data" },
            { "IDAT split by another chunk", File(ihdr, Chunk("IDAT", Deflate([0, 9])), Chunk("tEXt", [65, 0, 66]), Chunk("IDAT", Deflate([9, 9])), iend), "not consecutive" },
            { "too few rows", File(Chunk("IHDR", Header(1, 2, 8, 2)), idat, iend), "truncated: the image data holds 4 of the 8 bytes" },
            { "not zlib", File(ihdr, Chunk("IDAT", [1, 2, 3, 4, 5, 6]), iend), "zlib" },
            { "filter type 7", File(ihdr, Chunk("IDAT", Deflate([7, 9, 9, 9])), iend), "filter type 7" },
            { "palette without PLTE", File(Chunk("IHDR", Header(1, 1, 8, 3)), Chunk("IDAT", Deflate([0, 0])), iend), "without a PLTE" },
            { "palette index past the end", File(Chunk("IHDR", Header(1, 1, 8, 3)), Chunk("PLTE", [1, 2, 3]), Chunk("IDAT", Deflate([0, 1])), iend), "palette entry 1" },
            { "PLTE of 4 bytes", File(Chunk("IHDR", Header(1, 1, 8, 3)), Chunk("PLTE", [1, 2, 3, 4]), Chunk("IDAT", Deflate([0, 0])), iend), "PLTE" },
            { "unknown critical chunk", File(ihdr, Chunk("ABCD", []), idat, iend), "unknown critical chunk ABCD" },
            { "garbage chunk type", File(ihdr, [0, 0, 0, 0, 1, 2, 3, 4, 0, 0, 0, 0], idat, iend), "no valid chunk type" },
        };
        // Every cut of a good file, after the signature, is truncated.
        for (var length = Signature.Length; length < good.Length; length += 5)
            data.Add($"cut at {length}", good[..length], "truncated");
        return data;
    }

    [Theory]
    [MemberData(nameof(DamagedFiles))]
    public void DamagedFilesGiveOneErrorNamingTheFileAndTheProblem(string what, byte[] png, string problem)
    {
        var error = Assert.Throws<UserError>(() => PngDecoder.Decode(png, Name));
        Assert.True(error.Message.StartsWith(Name + ": ") && error.Message.Contains(problem) && !error.Message.Contains('\n'),
            $"{what}: expected one line '{Name}: …{problem}…', got '{error.Message}'");
    }

    [Fact]
    public void MissingFileAndDirectoryAreUserErrors()
    {
        var missing = Path.Combine(_scratch.Path, "nowhere.png");
        Assert.Equal($"{missing}: no such file", Assert.Throws<UserError>(() => PngDecoder.Read(missing)).Message);
        Assert.StartsWith(_scratch.Path + ": ", Assert.Throws<UserError>(() => PngDecoder.Read(_scratch.Path)).Message);
    }

    private static int Grey(int sample, int depth) => depth switch
    {
        1 => new[] { 0, 255 }[sample],
        2 => new[] { 0, 85, 170, 255 }[sample],
        4 => sample * 17,
        _ => sample,
    };

    private static int OverBlack(int value, int alpha) => (int)Math.Round(value * alpha / 255.0, MidpointRounding.AwayFromZero);
}
