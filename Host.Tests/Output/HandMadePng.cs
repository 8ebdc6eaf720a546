using System.Buffers.Binary;
using System.IO.Compression;
using System.Text;

namespace QuantumRayTracing.Tests.Output;

/// <summary>
/// Builds PNG files byte by byte from the PNG specification, for decoder tests: any colour type and bit depth,
/// rows filtered with any filter type, chunks in any order, damaged on purpose where a test wants it.
/// Shares no code with the host's encoder or decoder (the CRC is <see cref="PngTestDecoder.BitwiseCrc32"/>).
/// </summary>
internal static class HandMadePng
{
    public static readonly byte[] Signature = [0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A];

    public static byte[] Header(long width, long height, int depth, int colour, int interlace = 0)
    {
        var header = new byte[13];
        BinaryPrimitives.WriteUInt32BigEndian(header, (uint)width);
        BinaryPrimitives.WriteUInt32BigEndian(header.AsSpan(4), (uint)height);
        header[8] = (byte)depth;
        header[9] = (byte)colour;
        header[12] = (byte)interlace;
        return header;
    }

    /// <summary>Length, type, data, CRC of type and data (PNG spec, section 5.3).</summary>
    public static byte[] Chunk(string type, byte[] data)
    {
        var typeAndData = Encoding.ASCII.GetBytes(type).Concat(data).ToArray();
        var chunk = new byte[12 + data.Length];
        BinaryPrimitives.WriteInt32BigEndian(chunk, data.Length);
        typeAndData.CopyTo(chunk, 4);
        BinaryPrimitives.WriteUInt32BigEndian(chunk.AsSpan(8 + data.Length), PngTestDecoder.BitwiseCrc32(typeAndData));
        return chunk;
    }

    public static byte[] File(params byte[][] chunks) => [.. Signature, .. chunks.SelectMany(c => c)];

    public static byte[] Deflate(byte[] raw)
    {
        using var compressed = new MemoryStream();
        using (var zlib = new ZLibStream(compressed, CompressionLevel.Fastest, leaveOpen: true)) zlib.Write(raw);
        return compressed.ToArray();
    }

    /// <summary>Samples packed into bytes, most significant bits first, the last byte padded with zeros.</summary>
    public static byte[] Pack(IReadOnlyList<int> samples, int depth)
    {
        var bytes = new byte[(samples.Count * depth + 7) / 8];
        for (var i = 0; i < samples.Count; i++)
        {
            var bit = i * depth;
            bytes[bit / 8] |= (byte)(samples[i] << (8 - depth - bit % 8));
        }
        return bytes;
    }

    /// <summary>
    /// Rows filtered as the PNG spec's section 9.2 defines, row y with filter <paramref name="filterOf"/>(y), each preceded by
    /// its filter byte. <paramref name="unit"/>: bytes per complete pixel, at least 1.
    /// </summary>
    public static byte[] Filter(IReadOnlyList<byte[]> rows, int unit, Func<int, int> filterOf)
    {
        var output = new List<byte>();
        var above = new byte[rows[0].Length];
        for (var y = 0; y < rows.Count; y++)
        {
            var row = rows[y];
            var filter = filterOf(y);
            output.Add((byte)filter);
            for (var i = 0; i < row.Length; i++)
            {
                int a = i >= unit ? row[i - unit] : 0, b = above[i], c = i >= unit ? above[i - unit] : 0;
                var predicted = filter switch
                {
                    0 => 0,
                    1 => a,
                    2 => b,
                    3 => (a + b) / 2,
                    4 => PaethPredictor(a, b, c),
                    _ => throw new ArgumentOutOfRangeException(nameof(filterOf)),
                };
                output.Add((byte)(row[i] - predicted));
            }
            above = row;
        }
        return [.. output];
    }

    // Written as the spec's pseudocode states it, in the order of its three distances.
    private static int PaethPredictor(int a, int b, int c)
    {
        var p = a + b - c;
        var pa = Math.Abs(p - a);
        var pb = Math.Abs(p - b);
        var pc = Math.Abs(p - c);
        if (pa <= pb && pa <= pc) return a;
        if (pb <= pc) return b;
        return c;
    }

    /// <summary>A complete file: IHDR, <paramref name="before"/> chunks, one IDAT of the filtered rows, IEND.</summary>
    public static byte[] Image(int width, int depth, int colour, IReadOnlyList<int[]> sampleRows, Func<int, int> filterOf, params byte[][] before)
    {
        var channels = colour switch { 2 => 3, 4 => 2, 6 => 4, _ => 1 };
        var rows = sampleRows.Select(r => Pack(r, depth)).ToArray();
        var unit = Math.Max(1, channels * depth / 8);
        return File([Chunk("IHDR", Header(width, sampleRows.Count, depth, colour)), .. before,
            Chunk("IDAT", Deflate(Filter(rows, unit, filterOf))), Chunk("IEND", [])]);
    }
}
