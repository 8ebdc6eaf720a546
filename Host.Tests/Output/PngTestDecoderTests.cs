using System.Buffers.Binary;
using System.IO.Compression;
using System.Text;

namespace QuantumRayTracing.Tests.Output;

/// <summary>
/// The test decoder is itself checked against known answers, because the encoder only emits None, Sub and Up:
/// without this, a wrong Average or Paeth inverse (or a wrong CRC) would go unnoticed.
/// </summary>
public class PngTestDecoderTests
{
    [Fact]
    public void Crc32MatchesTheStandardCheckValues()
    {
        // The CRC-32 check value from the catalogue of parametrised CRCs, and the CRC every PNG ends with.
        Assert.Equal(0xCBF43926u, PngTestDecoder.BitwiseCrc32("123456789"u8));
        Assert.Equal(0xAE426082u, PngTestDecoder.BitwiseCrc32("IEND"u8));
    }

    [Fact]
    public void UndoesEveryFilterType()
    {
        // A 2x5 image, one row per filter type; filtered bytes worked out by hand from the PNG spec, section 9.
        byte[] scanlines =
        [
            1, 10, 20, 30, 30, 30, 30,     // Sub:     (10,20,30) (40,50,60)
            3, 10, 15, 20, 73, 224, 254,   // Average: (15,25,35) (100,5,45); floor((15+40)/2) = 27, 5-37 wraps to 224
            4, 185, 20, 236, 10, 45, 75,   // Paeth:   (200,45,15) (210,70,90); second pixel picks a, c, and a on the pa = pc tie
            2, 57, 213, 244, 50, 191, 172, // Up:      (1,2,3) (4,5,6)
            0, 7, 8, 9, 10, 11, 12,        // None:    (7,8,9) (10,11,12)
        ];
        var decoded = PngTestDecoder.Decode(HandMadePng(2, 5, scanlines));

        byte[,] expected =
        {
            { 10, 20, 30, 40, 50, 60 },
            { 15, 25, 35, 100, 5, 45 },
            { 200, 45, 15, 210, 70, 90 },
            { 1, 2, 3, 4, 5, 6 },
            { 7, 8, 9, 10, 11, 12 },
        };
        for (var y = 0; y < 5; y++)
            for (var x = 0; x < 2; x++)
                Assert.Equal((expected[y, 3 * x], expected[y, 3 * x + 1], expected[y, 3 * x + 2]), decoded.Image.GetPixel(x, y));
        Assert.Equal([1, 3, 4, 2, 0], decoded.RowFilters);
    }

    [Fact]
    public void RejectsACorruptedChunk()
    {
        var png = HandMadePng(1, 1, [0, 1, 2, 3]);
        png[^20] ^= 0x01; // a byte inside the IDAT data
        Assert.Throws<InvalidDataException>(() => PngTestDecoder.Decode(png));
    }

    private static byte[] HandMadePng(int width, int height, byte[] scanlines)
    {
        using var png = new MemoryStream();
        png.Write([0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A]);
        var header = new byte[13];
        BinaryPrimitives.WriteInt32BigEndian(header, width);
        BinaryPrimitives.WriteInt32BigEndian(header.AsSpan(4), height);
        header[8] = 8;
        header[9] = 2;
        Chunk(png, "IHDR", header);
        using (var compressed = new MemoryStream())
        {
            using (var zlib = new ZLibStream(compressed, CompressionLevel.Fastest, leaveOpen: true))
                zlib.Write(scanlines);
            Chunk(png, "IDAT", compressed.ToArray());
        }
        Chunk(png, "IEND", []);
        return png.ToArray();
    }

    private static void Chunk(Stream png, string type, byte[] data)
    {
        var typeAndData = Encoding.ASCII.GetBytes(type).Concat(data).ToArray();
        var word = new byte[4];
        BinaryPrimitives.WriteInt32BigEndian(word, data.Length);
        png.Write(word);
        png.Write(typeAndData);
        BinaryPrimitives.WriteUInt32BigEndian(word, PngTestDecoder.BitwiseCrc32(typeAndData));
        png.Write(word);
    }
}
