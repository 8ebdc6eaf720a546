using System.Buffers.Binary;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Tests.Output;

public sealed class PngEncoderTests : IDisposable
{
    private readonly ScratchDirectory _scratch = new("qrt-png-");

    public static TheoryData<string> ImageNames => new(Images.Keys);

    // Sizes chosen to hit the edges: a single pixel, rows shorter than the Sub filter's reach, an odd width.
    private static readonly Dictionary<string, Func<RgbImage>> Images = new()
    {
        ["1x1"] = () => Filled(1, 1, (_, _) => (200, 100, 50)),
        ["3x2"] = () => Filled(3, 2, (x, y) => ((byte)(80 * x), (byte)(255 - 100 * y), (byte)(x * y * 90))),
        ["17x5 random"] = () => Noise(17, 5, seed: 20240601),
        ["64x48 gradient"] = () => RgbImage.FromLinear(64, 48, (x, y) => (x / 63.0, y / 47.0, 1 - (x + y) / 109.0)),
    };

    [Theory]
    [MemberData(nameof(ImageNames))]
    public void RoundTripsThroughTheTestDecoder(string name)
    {
        var image = Images[name]();
        var decoded = PngTestDecoder.Decode(PngEncoder.Encode(image)).Image;
        AssertSamePixels(image, decoded.Width, decoded.Height, decoded.Pixels.ToArray());
    }

    [Theory]
    [MemberData(nameof(ImageNames))]
    public async Task NodeDecodesTheSamePixels(string name)
    {
        var image = Images[name]();
        var path = Path.Combine(_scratch.Path, "node.png");
        PngEncoder.Write(image, path);
        var decoded = await NodePngDecoder.DecodeAsync(path);
        AssertSamePixels(image, decoded.Width, decoded.Height, decoded.Rgb);
    }

    [Fact]
    public void StartsWithTheSignatureAndABigEndianHeader()
    {
        var png = PngEncoder.Encode(new RgbImage(300, 2));
        Assert.Equal([0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A], png[..8]);
        Assert.Equal(13, BinaryPrimitives.ReadInt32BigEndian(png.AsSpan(8)));
        Assert.Equal("IHDR"u8.ToArray(), png[12..16]);
        Assert.Equal([0, 0, 0x01, 0x2C, 0, 0, 0, 2, 8, 2, 0, 0, 0], png[16..29]); // 300 = 0x012C, 8-bit RGB
        var chunks = PngTestDecoder.ReadChunks(png);
        Assert.Equal(["IHDR", "tEXt", "IDAT", "IEND"], chunks.Select(c => c.Type));
        // tEXt is keyword, NUL, text (PNG spec 11.3.4.3): the marker that lets a later run replace this file.
        Assert.Equal("Software\0QuantumRayTracing"u8.ToArray(), chunks[1].Data);
    }

    [Fact]
    public void RecognisesOnlyItsOwnFiles()
    {
        var directory = Directory.CreateTempSubdirectory("qrt-png-");
        try
        {
            var ours = Path.Combine(directory.FullName, "ours.png");
            var foreign = Path.Combine(directory.FullName, "foreign.png");
            var text = Path.Combine(directory.FullName, "notes.png");
            PngEncoder.Write(new RgbImage(2, 2), ours);
            var bytes = PngEncoder.Encode(new RgbImage(2, 2));
            // The same PNG without its tEXt chunk: 8 signature bytes + 25 IHDR bytes, then skip 12 + 26 tEXt bytes.
            File.WriteAllBytes(foreign, [.. bytes[..33], .. bytes[(33 + 12 + 26)..]]);
            File.WriteAllText(text, "Software\0QuantumRayTracing");
            Assert.True(PngEncoder.IsWrittenHere(ours));
            Assert.False(PngEncoder.IsWrittenHere(foreign));
            Assert.False(PngEncoder.IsWrittenHere(text));
        }
        finally
        {
            directory.Delete(recursive: true);
        }
    }

    [Fact]
    public void PicksSubOrUpWhereTheyPredictBetter()
    {
        // Every row is the same horizontal ramp: Sub predicts the first row, Up (all zeros) every row after it.
        var image = Filled(40, 4, (x, _) => ((byte)(3 * x), (byte)(100 + x), 7));
        var filters = PngTestDecoder.Decode(PngEncoder.Encode(image)).RowFilters;
        Assert.Equal([1, 2, 2, 2], filters);
    }

    [Fact]
    public void SameImageGivesSameBytes()
    {
        var first = PngEncoder.Encode(Noise(33, 9, seed: 7));
        Assert.Equal(first, PngEncoder.Encode(Noise(33, 9, seed: 7)));
        var image = Noise(33, 9, seed: 7);
        Assert.Equal(PngEncoder.Encode(image), PngEncoder.Encode(image));
    }

    [Fact]
    public void WriteLeavesOnlyTheFinishedFile()
    {
        var image = Noise(5, 4, seed: 3);
        var path = Path.Combine(_scratch.Path, "image.png");
        PngEncoder.Write(image, path);
        Assert.Equal(PngEncoder.Encode(image), File.ReadAllBytes(path));
        Assert.Equal([path], Directory.GetFiles(_scratch.Path));
    }

    [Fact]
    public void WriteReplacesAnExistingFileByRenameNotInPlace()
    {
        var path = Path.Combine(_scratch.Path, "image.png");
        File.WriteAllText(path, "old contents");
        // A reader holding the old file keeps seeing the old contents only if the new file was renamed over it;
        // writing in place would change what this handle reads.
        using var reader = new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.ReadWrite | FileShare.Delete);

        var image = Noise(6, 6, seed: 11);
        PngEncoder.Write(image, path);

        Assert.Equal("old contents", new StreamReader(reader).ReadToEnd());
        Assert.Equal(PngEncoder.Encode(image), File.ReadAllBytes(path));
        Assert.Equal([path], Directory.GetFiles(_scratch.Path));
    }

    [Fact]
    public void WriteIntoAMissingDirectoryThrowsAndLeavesNothing()
    {
        var missing = Path.Combine(_scratch.Path, "no-such-directory");
        Assert.Throws<DirectoryNotFoundException>(() => PngEncoder.Write(new RgbImage(2, 2), Path.Combine(missing, "image.png")));
        Assert.False(Directory.Exists(missing));
        Assert.Empty(Directory.EnumerateFileSystemEntries(_scratch.Path));
    }

    [Fact]
    public void FailedRenameRemovesTheTemporaryFile()
    {
        // The target is a directory, so the temporary file is written but cannot be renamed over it.
        var path = Path.Combine(_scratch.Path, "taken");
        Directory.CreateDirectory(path);
        Assert.ThrowsAny<IOException>(() => PngEncoder.Write(new RgbImage(2, 2), path));
        Assert.Equal([path], Directory.GetFileSystemEntries(_scratch.Path));
    }

    [Fact]
    public void LeavesAFileNamedLikeATemporaryOneAlone()
    {
        var path = Path.Combine(_scratch.Path, "x.png");
        File.WriteAllText(path + ".tmp", "the user's notes");
        PngEncoder.Write(new RgbImage(2, 2), path);
        Assert.Equal("the user's notes", File.ReadAllText(path + ".tmp"));
        Assert.Equal(2, Directory.GetFileSystemEntries(_scratch.Path).Length);
    }

    private static void AssertSamePixels(RgbImage expected, int width, int height, byte[] rgb)
    {
        Assert.Equal((expected.Width, expected.Height), (width, height));
        Assert.Equal(expected.Pixels.ToArray(), rgb);
    }

    private static RgbImage Filled(int width, int height, Func<int, int, (byte R, byte G, byte B)> colour)
    {
        var image = new RgbImage(width, height);
        for (var y = 0; y < height; y++)
            for (var x = 0; x < width; x++)
            {
                var (r, g, b) = colour(x, y);
                image.SetPixel(x, y, r, g, b);
            }
        return image;
    }

    private static RgbImage Noise(int width, int height, int seed)
    {
        var random = new Random(seed);
        var image = new RgbImage(width, height);
        var rgb = new byte[3];
        for (var y = 0; y < height; y++)
            for (var x = 0; x < width; x++)
            {
                random.NextBytes(rgb);
                image.SetPixel(x, y, rgb[0], rgb[1], rgb[2]);
            }
        return image;
    }

    public void Dispose() => _scratch.Dispose();
}
