using System.Buffers.Binary;
using System.IO.Hashing;
using System.Text;
using SkiaSharp;

namespace QuantumRayTracing.Output;

/// <summary>
/// Encodes an <see cref="RgbImage"/> as an 8-bit RGB PNG with SkiaSharp, and adds one tEXt chunk,
/// Software = <see cref="Software"/>, right after the header: the mark by which <see cref="IsWrittenHere"/>
/// tells the files this program wrote (and may replace) from anyone else's. The encoder's settings are
/// fixed, so the same pixels always give the same bytes.
/// </summary>
public static class PngWriter
{
    /// <summary>The value of the tEXt "Software" chunk of every PNG written here.</summary>
    public const string Software = "QuantumRayTracing";

    private static ReadOnlySpan<byte> Signature => [0x89, (byte)'P', (byte)'N', (byte)'G', 0x0D, 0x0A, 0x1A, 0x0A];

    private static byte[] SoftwareText => Encoding.Latin1.GetBytes("Software\0" + Software);

    // The signature and the IHDR chunk (length, type, 13 bytes of data, CRC): the tEXt chunk goes after them.
    private const int HeaderEnd = 8 + 12 + 13;

    /// <summary>Whether the file at <paramref name="path"/> is a PNG written here (it carries the Software mark near its start).</summary>
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
        using var bitmap = SkiaPixels.ToBitmap(image);
        using var pixmap = bitmap.PeekPixels();
        using var encoded = pixmap.Encode(new SKPngEncoderOptions(SKPngEncoderFilterFlags.AllFilters, zLibLevel: 9))
            ?? throw new InvalidOperationException($"SkiaSharp could not encode a {image.Width}x{image.Height} PNG");
        return WithSoftwareChunk(encoded.AsSpan());
    }

    /// <summary>
    /// Writes <paramref name="image"/> to <paramref name="path"/>, replacing an existing file, through
    /// <see cref="AtomicFile"/>, so a failure never leaves a partial or truncated image behind.
    /// </summary>
    public static void Write(RgbImage image, string path) => AtomicFile.WriteAllBytes(path, Encode(image));

    private static byte[] WithSoftwareChunk(ReadOnlySpan<byte> png)
    {
        var text = SoftwareText;
        var chunk = new byte[12 + text.Length];
        BinaryPrimitives.WriteUInt32BigEndian(chunk, (uint)text.Length);
        Encoding.ASCII.GetBytes("tEXt", chunk.AsSpan(4));
        text.CopyTo(chunk, 8);
        // The CRC covers the chunk type and data, not the length (PNG spec, section 5.3).
        BinaryPrimitives.WriteUInt32BigEndian(chunk.AsSpan(8 + text.Length), Crc32.HashToUInt32(chunk.AsSpan(4, 4 + text.Length)));
        return [.. png[..HeaderEnd], .. chunk, .. png[HeaderEnd..]];
    }
}
