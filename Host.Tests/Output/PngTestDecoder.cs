using System.Buffers.Binary;
using System.IO.Compression;
using System.Text;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Tests.Output;

/// <summary>
/// A minimal PNG reader for 8-bit truecolour, non-interlaced files, written from the PNG specification and
/// sharing no code with <see cref="PngEncoder"/>, so a round trip checks the encoder rather than itself.
/// Every chunk CRC is verified with a bitwise CRC-32, and all five filter types are undone.
/// </summary>
internal static class PngTestDecoder
{
    private static readonly byte[] Signature = [0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A];

    /// <summary>A chunk as it appears in the file.</summary>
    public sealed record Chunk(string Type, byte[] Data);

    /// <summary>All chunks in file order; throws if the signature, a length or a CRC is wrong.</summary>
    /// <summary>The image of the PNG file at <paramref name="path"/>.</summary>
    public static RgbImage ReadImage(string path) => Decode(File.ReadAllBytes(path)).Image;

    public static List<Chunk> ReadChunks(byte[] png)
    {
        if (png.Length < Signature.Length || !png.AsSpan(0, Signature.Length).SequenceEqual(Signature))
            throw new InvalidDataException("not a PNG signature");
        var chunks = new List<Chunk>();
        var at = Signature.Length;
        while (at < png.Length)
        {
            if (png.Length - at < 12) throw new InvalidDataException($"truncated chunk header at {at}");
            var length = BinaryPrimitives.ReadUInt32BigEndian(png.AsSpan(at));
            if (length > int.MaxValue || length > png.Length - at - 12) throw new InvalidDataException($"chunk length {length} at {at} runs past the end");
            var typeAndData = png.AsSpan(at + 4, 4 + (int)length);
            var stored = BinaryPrimitives.ReadUInt32BigEndian(png.AsSpan(at + 8 + (int)length));
            var type = Encoding.ASCII.GetString(typeAndData[..4]);
            var computed = BitwiseCrc32(typeAndData);
            if (stored != computed) throw new InvalidDataException($"{type} CRC is {stored:X8}, expected {computed:X8}");
            chunks.Add(new Chunk(type, typeAndData[4..].ToArray()));
            at += 12 + (int)length;
        }
        return chunks;
    }

    /// <summary>A decoded image and the filter type each row was stored with.</summary>
    public sealed record Decoded(RgbImage Image, byte[] RowFilters);

    /// <summary>Decodes <paramref name="png"/>; throws on anything an 8-bit RGB, non-interlaced PNG would not contain.</summary>
    public static Decoded Decode(byte[] png)
    {
        var chunks = ReadChunks(png);
        if (chunks.Count < 3 || chunks[0].Type != "IHDR" || chunks[^1].Type != "IEND" || chunks[^1].Data.Length != 0)
            throw new InvalidDataException("PNG must start with IHDR and end with an empty IEND");

        var header = chunks[0].Data;
        if (header.Length != 13) throw new InvalidDataException($"IHDR has {header.Length} bytes");
        var width = checked((int)BinaryPrimitives.ReadUInt32BigEndian(header));
        var height = checked((int)BinaryPrimitives.ReadUInt32BigEndian(header.AsSpan(4)));
        if (header[8] != 8 || header[9] != 2 || header[10] != 0 || header[11] != 0 || header[12] != 0)
            throw new InvalidDataException($"unsupported IHDR: depth {header[8]}, colour {header[9]}, compression {header[10]}, filter {header[11]}, interlace {header[12]}");

        // The image data is the concatenation of all IDAT chunks, which must be consecutive.
        var firstIdat = chunks.FindIndex(c => c.Type == "IDAT");
        var lastIdat = chunks.FindLastIndex(c => c.Type == "IDAT");
        if (firstIdat < 0) throw new InvalidDataException("no IDAT");
        if (chunks.Skip(firstIdat).Take(lastIdat - firstIdat + 1).Any(c => c.Type != "IDAT"))
            throw new InvalidDataException("IDAT chunks are not consecutive");
        var compressed = chunks.Where(c => c.Type == "IDAT").SelectMany(c => c.Data).ToArray();

        var stride = width * 3;
        var raw = Inflate(compressed);
        if (raw.Length != height * (stride + 1))
            throw new InvalidDataException($"inflated {raw.Length} bytes, expected {height * (stride + 1)}");

        var image = new RgbImage(width, height);
        var filters = new byte[height];
        var previous = new byte[stride];
        var current = new byte[stride];
        for (var y = 0; y < height; y++)
        {
            var line = raw.AsSpan(y * (stride + 1), stride + 1);
            filters[y] = line[0];
            Unfilter(line[0], line[1..], previous, current);
            for (var x = 0; x < width; x++)
                image.SetPixel(x, y, current[3 * x], current[3 * x + 1], current[3 * x + 2]);
            (previous, current) = (current, previous);
        }
        return new Decoded(image, filters);
    }

    private static byte[] Inflate(byte[] zlibData)
    {
        using var input = new MemoryStream(zlibData);
        using var zlib = new ZLibStream(input, CompressionMode.Decompress);
        using var output = new MemoryStream();
        zlib.CopyTo(output);
        return output.ToArray();
    }

    // PNG spec, section 9.2, with bpp = 3. "a" is the byte to the left, "b" above, "c" above-left.
    private static void Unfilter(byte filter, ReadOnlySpan<byte> line, byte[] previous, byte[] current)
    {
        for (var i = 0; i < line.Length; i++)
        {
            int a = i >= 3 ? current[i - 3] : 0, b = previous[i], c = i >= 3 ? previous[i - 3] : 0;
            var predictor = filter switch
            {
                0 => 0,
                1 => a,
                2 => b,
                3 => (a + b) / 2,
                4 => Paeth(a, b, c),
                _ => throw new InvalidDataException($"filter type {filter}"),
            };
            current[i] = (byte)(line[i] + predictor);
        }
    }

    private static int Paeth(int a, int b, int c)
    {
        int p = a + b - c, pa = Math.Abs(p - a), pb = Math.Abs(p - b), pc = Math.Abs(p - c);
        if (pa <= pb && pa <= pc) return a;
        return pb <= pc ? b : c;
    }

    // Deliberately the slow bit-at-a-time form, so it cannot share a table bug with the encoder.
    public static uint BitwiseCrc32(ReadOnlySpan<byte> bytes)
    {
        var crc = 0xFFFFFFFFu;
        foreach (var value in bytes)
        {
            crc ^= value;
            for (var bit = 0; bit < 8; bit++)
                crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1)));
        }
        return ~crc;
    }
}
