using System.Buffers.Binary;
using System.IO.Compression;
using System.Text;

namespace QuantumRayTracing.Output;

/// <summary>
/// Reads a PNG into an <see cref="RgbImage"/>: greyscale (1, 2, 4, 8 bits), greyscale + alpha, RGB, RGBA and
/// palette (1, 2, 4, 8 bits) images, non-interlaced, with every chunk CRC checked and all five filter types
/// undone (PNG spec, sections 5-9). Transparency (an alpha channel or tRNS) is composited over black; grey
/// becomes R = G = B. Interlaced and 16-bit files are refused. Every problem is a <see cref="UserError"/>
/// naming the file and what is wrong with it.
/// </summary>
public static class PngDecoder
{
    /// <summary>Largest width or height accepted.</summary>
    public const int MaxSide = 32768;

    /// <summary>Largest width × height accepted (64 Mpixels, 192 MB as RGB).</summary>
    public const long MaxPixels = 1L << 26;

    private static ReadOnlySpan<byte> Signature => [0x89, (byte)'P', (byte)'N', (byte)'G', 0x0D, 0x0A, 0x1A, 0x0A];

    /// <summary>Reads and decodes the file at <paramref name="path"/>.</summary>
    public static RgbImage Read(string path)
    {
        byte[] bytes;
        try
        {
            bytes = File.ReadAllBytes(path);
        }
        catch (Exception e) when (e is FileNotFoundException or DirectoryNotFoundException)
        {
            throw new UserError($"{path}: no such file");
        }
        catch (UnauthorizedAccessException)
        {
            throw new UserError($"{path}: cannot be read (permission denied, or it is a directory)");
        }
        catch (IOException e)
        {
            throw new UserError($"{path}: cannot be read: {e.Message}");
        }
        return Decode(bytes, path);
    }

    /// <summary>Decodes <paramref name="png"/>; <paramref name="name"/> (the file's path) starts every error message.</summary>
    public static RgbImage Decode(byte[] png, string name)
    {
        ArgumentNullException.ThrowIfNull(png);
        UserError Fail(string problem) => new($"{name}: {problem}");

        if (png.Length < Signature.Length || !png.AsSpan(0, Signature.Length).SequenceEqual(Signature))
            throw Fail("not a PNG file (it does not start with the PNG signature)");

        Header? header = null;
        byte[]? palette = null;
        byte[]? transparency = null;
        var data = new MemoryStream();
        var idatState = 0; // 0: none yet, 1: inside the IDAT run, 2: after it
        var at = Signature.Length;
        while (true)
        {
            if (at == png.Length) throw Fail("truncated: the file ends before the IEND chunk");
            if (png.Length - at < 12) throw Fail($"truncated: the file ends inside a chunk header at byte {at}");
            var length = BinaryPrimitives.ReadUInt32BigEndian(png.AsSpan(at));
            var typeBytes = png.AsSpan(at + 4, 4);
            if (!IsChunkType(typeBytes)) throw Fail($"damaged: no valid chunk type at byte {at}");
            var type = Encoding.ASCII.GetString(typeBytes);
            if (length > (uint)(png.Length - at - 12)) throw Fail($"truncated: the {type} chunk at byte {at} runs past the end of the file");
            var body = png.AsSpan(at + 8, (int)length);
            var stored = BinaryPrimitives.ReadUInt32BigEndian(png.AsSpan(at + 8 + (int)length));
            if (stored != Crc32.Of(typeBytes, body)) throw Fail($"bad CRC in the {type} chunk at byte {at} (the file is damaged)");
            if (header is null && type != "IHDR") throw Fail($"the first chunk is {type}, not IHDR");
            if (idatState == 1 && type != "IDAT") idatState = 2;

            switch (type)
            {
                case "IHDR":
                    if (header is not null) throw Fail("more than one IHDR chunk");
                    header = Header.Parse(body, Fail);
                    break;
                case "PLTE":
                    if (idatState != 0) throw Fail("the PLTE chunk comes after the image data");
                    if (header!.ColourType is 0 or 4) throw Fail("a greyscale PNG must not have a PLTE chunk");
                    if (body.Length == 0 || body.Length % 3 != 0 || body.Length / 3 > 256)
                        throw Fail($"the PLTE chunk has {body.Length} bytes, not 3 per entry for 1 to 256 entries");
                    palette = body.ToArray();
                    break;
                case "tRNS":
                    // Ancillary: a malformed one is ignored, as decoders commonly do.
                    if (header!.TransparencyLength(palette) is { } expected && (header.ColourType == 3 ? body.Length <= expected : body.Length == expected))
                        transparency = body.ToArray();
                    break;
                case "IDAT":
                    if (idatState == 2) throw Fail("the IDAT chunks are not consecutive");
                    idatState = 1;
                    data.Write(body);
                    break;
                case "IEND":
                    break;
                default:
                    // A critical chunk (first letter upper case) cannot be skipped safely; an ancillary one can.
                    if (char.IsAsciiLetterUpper(type[0])) throw Fail($"unknown critical chunk {type}");
                    break;
            }
            at += 12 + (int)length;
            if (type == "IEND") break;
        }

        if (idatState == 0) throw Fail("no image data (IDAT chunk)");
        if (header!.ColourType == 3 && palette is null) throw Fail("a palette image without a PLTE chunk");
        var raw = Inflate(data.ToArray(), header.RawLength, Fail);
        return Reconstruct(header, raw, palette, transparency, Fail);
    }

    private static bool IsChunkType(ReadOnlySpan<byte> type)
    {
        foreach (var b in type)
            if (!char.IsAsciiLetter((char)b)) return false;
        return true;
    }

    // Exactly `expected` bytes: fewer is a truncated or damaged stream; anything after them is ignored (as libpng does).
    private static byte[] Inflate(byte[] compressed, int expected, Func<string, UserError> fail)
    {
        var raw = new byte[expected];
        int read;
        try
        {
            using var zlib = new ZLibStream(new MemoryStream(compressed), CompressionMode.Decompress);
            read = zlib.ReadAtLeast(raw, expected, throwOnEndOfStream: false);
        }
        catch (InvalidDataException)
        {
            throw fail("damaged: the image data is not a valid zlib stream");
        }
        if (read < expected) throw fail($"truncated: the image data holds {read} of the {expected} bytes the image needs");
        return raw;
    }

    private static RgbImage Reconstruct(Header header, byte[] raw, byte[]? palette, byte[]? transparency, Func<string, UserError> fail)
    {
        var (width, height) = (header.Width, header.Height);
        var rowBytes = header.RowBytes;
        var bpp = header.FilterUnit;
        var image = new RgbImage(width, height);
        var previous = new byte[rowBytes];
        var current = new byte[rowBytes];
        var samples = new int[width * header.Channels];
        for (var y = 0; y < height; y++)
        {
            var line = raw.AsSpan(y * (rowBytes + 1), rowBytes + 1);
            if (line[0] > 4) throw fail($"damaged: row {y} has filter type {line[0]} (PNG defines 0 to 4)");
            Unfilter(line[0], line[1..], previous, current, bpp);
            Unpack(current, header.BitDepth, samples);
            for (var x = 0; x < width; x++)
            {
                var (r, g, b, a) = Colour(header, samples, x, palette, transparency, y, fail);
                image.SetPixel(x, y, OverBlack(r, a), OverBlack(g, a), OverBlack(b, a));
            }
            (previous, current) = (current, previous);
        }
        return image;
    }

    // PNG spec, section 9.2: a is the byte `bpp` to the left, b the byte above, c the byte above a; the row above the first is zeros.
    private static void Unfilter(byte filter, ReadOnlySpan<byte> line, byte[] previous, byte[] current, int bpp)
    {
        for (var i = 0; i < line.Length; i++)
        {
            int a = i >= bpp ? current[i - bpp] : 0, b = previous[i], c = i >= bpp ? previous[i - bpp] : 0;
            var predictor = filter switch
            {
                1 => a,
                2 => b,
                3 => (a + b) >> 1,
                4 => Paeth(a, b, c),
                _ => 0,
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

    // Samples of one row, most significant bits first within a byte (PNG spec, section 7.2).
    private static void Unpack(byte[] row, int depth, int[] samples)
    {
        if (depth == 8)
        {
            for (var i = 0; i < samples.Length; i++) samples[i] = row[i];
            return;
        }
        var perByte = 8 / depth;
        var mask = (1 << depth) - 1;
        for (var i = 0; i < samples.Length; i++)
            samples[i] = (row[i / perByte] >> (8 - depth * (i % perByte + 1))) & mask;
    }

    private static (int R, int G, int B, int A) Colour(Header header, int[] s, int x, byte[]? palette, byte[]? transparency, int y, Func<string, UserError> fail)
    {
        switch (header.ColourType)
        {
            case 0:
                var grey = Scale(s[x], header.BitDepth);
                var keyed = transparency is not null && s[x] == BinaryPrimitives.ReadUInt16BigEndian(transparency);
                return (grey, grey, grey, keyed ? 0 : 255);
            case 2:
                var (r, g, b) = (s[3 * x], s[3 * x + 1], s[3 * x + 2]);
                var key = transparency is not null
                    && r == BinaryPrimitives.ReadUInt16BigEndian(transparency)
                    && g == BinaryPrimitives.ReadUInt16BigEndian(transparency.AsSpan(2))
                    && b == BinaryPrimitives.ReadUInt16BigEndian(transparency.AsSpan(4));
                return (r, g, b, key ? 0 : 255);
            case 3:
                var index = s[x];
                if (index >= palette!.Length / 3)
                    throw fail($"damaged: pixel ({x}, {y}) uses palette entry {index}, but the PLTE chunk has {palette.Length / 3} entries");
                var alpha = transparency is not null && index < transparency.Length ? transparency[index] : 255;
                return (palette[3 * index], palette[3 * index + 1], palette[3 * index + 2], alpha);
            case 4:
                return (s[2 * x], s[2 * x], s[2 * x], s[2 * x + 1]);
            default:
                return (s[4 * x], s[4 * x + 1], s[4 * x + 2], s[4 * x + 3]);
        }
    }

    // A sample of 1, 2 or 4 bits stretched to 0..255 (PNG spec, section 13.12: v · 255 / (2^depth − 1), exact for these depths).
    private static int Scale(int sample, int depth) => depth == 8 ? sample : sample * 255 / ((1 << depth) - 1);

    private static byte OverBlack(int value, int alpha) => (byte)((value * alpha + 127) / 255);

    /// <summary>The IHDR fields, checked (PNG spec, section 11.2.2).</summary>
    private sealed record Header(int Width, int Height, int BitDepth, int ColourType)
    {
        public int Channels => ColourType switch { 2 => 3, 4 => 2, 6 => 4, _ => 1 };

        /// <summary>Bytes of one row without its filter byte.</summary>
        public int RowBytes => (int)(((long)Width * Channels * BitDepth + 7) / 8);

        /// <summary>The inflated size: every row with its filter byte.</summary>
        public int RawLength => Height * (RowBytes + 1);

        /// <summary>The byte distance filters look back: a whole pixel, or one byte when pixels are smaller.</summary>
        public int FilterUnit => Math.Max(1, Channels * BitDepth / 8);

        /// <summary>The length a tRNS chunk must have (at most, for a palette), or null when this colour type takes none.</summary>
        public int? TransparencyLength(byte[]? palette) => ColourType switch
        {
            0 => 2,
            2 => 6,
            3 when palette is not null => palette.Length / 3,
            _ => null,
        };

        public static Header Parse(ReadOnlySpan<byte> body, Func<string, UserError> fail)
        {
            if (body.Length != 13) throw fail($"damaged: the IHDR chunk has {body.Length} bytes, not 13");
            var width = BinaryPrimitives.ReadUInt32BigEndian(body);
            var height = BinaryPrimitives.ReadUInt32BigEndian(body[4..]);
            int depth = body[8], colour = body[9];
            if (width == 0 || height == 0) throw fail($"the image has size {width}x{height}; both sides must be at least 1");
            if (width > MaxSide || height > MaxSide || (long)width * height > MaxPixels)
                throw fail($"the image is too large ({width}x{height}; at most {MaxSide} per side and {MaxPixels:N0} pixels)");
            int[] depths = colour switch
            {
                0 => [1, 2, 4, 8, 16],
                3 => [1, 2, 4, 8],
                2 or 4 or 6 => [8, 16],
                _ => throw fail($"unsupported colour type {colour} (PNG defines 0, 2, 3, 4 and 6)"),
            };
            if (!depths.Contains(depth)) throw fail($"bit depth {depth} is not valid for colour type {colour}");
            if (depth == 16) throw fail($"16-bit channels are not supported (colour type {colour}); save the image with 8 bits per channel");
            if (body[10] != 0) throw fail($"unknown compression method {body[10]}");
            if (body[11] != 0) throw fail($"unknown filter method {body[11]}");
            if (body[12] == 1) throw fail("interlaced (Adam7) PNGs are not supported; save the image without interlacing");
            if (body[12] != 0) throw fail($"unknown interlace method {body[12]}");
            return new Header((int)width, (int)height, depth, colour);
        }
    }
}
