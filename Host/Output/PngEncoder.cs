using System.Buffers.Binary;
using System.IO.Compression;
using System.Text;

namespace QuantumRayTracing.Output;

/// <summary>
/// Writes an <see cref="RgbImage"/> as an 8-bit truecolour PNG (no interlacing; one ancillary chunk,
/// tEXt Software = <see cref="Software"/>, which marks the files this program wrote). The output
/// depends only on the pixels, so the same image always gives the same bytes.
/// </summary>
public static class PngEncoder
{
    private static ReadOnlySpan<byte> Signature => [0x89, (byte)'P', (byte)'N', (byte)'G', 0x0D, 0x0A, 0x1A, 0x0A];

    private const int BytesPerPixel = 3;

    // PNG filter types (PNG spec, section 9.2). Average and Paeth are not tried: None/Sub/Up
    // already capture the smooth gradients a renderer produces, and keep the encoder easy to check.
    private const byte FilterNone = 0;
    private const byte FilterSub = 1;
    private const byte FilterUp = 2;

    /// <summary>The value of the tEXt "Software" chunk of every PNG written here.</summary>
    public const string Software = "QuantumRayTracing";

    private static byte[] SoftwareText => Encoding.Latin1.GetBytes("Software\0" + Software);

    /// <summary>Whether the file at <paramref name="path"/> is a PNG this encoder wrote (it carries the Software marker).</summary>
    public static bool IsWrittenHere(string path)
    {
        var head = new byte[256];
        int read;
        using (var file = File.OpenRead(path)) read = file.ReadAtLeast(head, head.Length, throwOnEndOfStream: false);
        return head.AsSpan(0, read).StartsWith(Signature) && head.AsSpan(0, read).IndexOf(SoftwareText) >= 0;
    }

    /// <summary>The complete PNG file for <paramref name="image"/>.</summary>
    public static byte[] Encode(RgbImage image)
    {
        ArgumentNullException.ThrowIfNull(image);
        using var png = new MemoryStream();
        png.Write(Signature);
        WriteChunk(png, "IHDR", Header(image));
        WriteChunk(png, "tEXt", SoftwareText);
        // One IDAT: a decoder concatenates IDATs anyway, and splitting them gains nothing in a file.
        WriteChunk(png, "IDAT", CompressScanlines(image));
        WriteChunk(png, "IEND", []);
        return png.ToArray();
    }

    /// <summary>
    /// Writes <paramref name="image"/> to <paramref name="path"/>, replacing an existing file. The PNG goes to
    /// a temporary file first and is renamed (<see cref="AtomicFile"/>), so a failure never leaves a partial or truncated image behind.
    /// </summary>
    public static void Write(RgbImage image, string path)
    {
        ArgumentNullException.ThrowIfNull(image);
        AtomicFile.WriteAllBytes(path, Encode(image));
    }

    private static byte[] Header(RgbImage image)
    {
        var header = new byte[13];
        BinaryPrimitives.WriteUInt32BigEndian(header.AsSpan(0), (uint)image.Width);
        BinaryPrimitives.WriteUInt32BigEndian(header.AsSpan(4), (uint)image.Height);
        header[8] = 8;  // bit depth
        header[9] = 2;  // colour type: truecolour (RGB)
        header[10] = 0; // compression method: deflate
        header[11] = 0; // filter method: adaptive, five filter types
        header[12] = 0; // interlace method: none
        return header;
    }

    private static byte[] CompressScanlines(RgbImage image)
    {
        var stride = image.Width * BytesPerPixel;
        var pixels = image.Pixels;
        var none = new byte[stride];
        var sub = new byte[stride];
        var up = new byte[stride];
        using var compressed = new MemoryStream();
        using (var zlib = new ZLibStream(compressed, CompressionLevel.Optimal, leaveOpen: true))
        {
            for (var y = 0; y < image.Height; y++)
            {
                var row = pixels.Slice(y * stride, stride);
                // The row above is all zeros for the first row (PNG spec, section 9.2), where Up equals None.
                var above = y == 0 ? ReadOnlySpan<byte>.Empty : pixels.Slice((y - 1) * stride, stride);
                row.CopyTo(none);
                for (var i = 0; i < stride; i++)
                {
                    sub[i] = (byte)(row[i] - (i >= BytesPerPixel ? row[i - BytesPerPixel] : 0));
                    up[i] = (byte)(row[i] - (y == 0 ? 0 : above[i]));
                }

                // Minimum sum of absolute differences (PNG spec, section 12.8): bytes read as signed, so
                // small negative differences count as small. Ties go to the earlier filter, which keeps it deterministic.
                var (filter, data) = (FilterNone, none);
                var best = SumOfAbsolute(none);
                var subSum = SumOfAbsolute(sub);
                if (subSum < best) (filter, data, best) = (FilterSub, sub, subSum);
                var upSum = SumOfAbsolute(up);
                if (upSum < best) (filter, data) = (FilterUp, up);

                zlib.WriteByte(filter);
                zlib.Write(data);
            }
        }
        return compressed.ToArray();
    }

    private static long SumOfAbsolute(byte[] filtered)
    {
        long sum = 0;
        foreach (var b in filtered) sum += Math.Abs((int)(sbyte)b);
        return sum;
    }

    private static void WriteChunk(Stream png, string type, ReadOnlySpan<byte> data)
    {
        Span<byte> word = stackalloc byte[4];
        BinaryPrimitives.WriteUInt32BigEndian(word, (uint)data.Length);
        png.Write(word);

        // The CRC covers the chunk type and data, not the length (PNG spec, section 5.3).
        var typeBytes = Encoding.ASCII.GetBytes(type);
        png.Write(typeBytes);
        png.Write(data);
        BinaryPrimitives.WriteUInt32BigEndian(word, Crc32.Of(typeBytes, data));
        png.Write(word);
    }
}
