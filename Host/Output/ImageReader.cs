using SkiaSharp;

namespace QuantumRayTracing.Output;

/// <summary>
/// Reads an image file into an <see cref="RgbImage"/> with SkiaSharp: PNG (any bit depth, interlaced, palette,
/// alpha), JPEG, WebP, BMP and GIF (its first frame). Transparency is composited over black. The declared size is
/// checked before any pixel is decoded, so a small file claiming a huge image is refused without allocating it.
/// Every problem is a <see cref="UserError"/> naming the file.
/// </summary>
public static class ImageReader
{
    /// <summary>Largest width or height accepted.</summary>
    public const int MaxSide = 32768;

    /// <summary>Largest width × height accepted (64 Mpixels, 192 MB as RGB).</summary>
    public const long MaxPixels = 1L << 26;

    private static ReadOnlySpan<byte> PngSignature => [0x89, (byte)'P', (byte)'N', (byte)'G', 0x0D, 0x0A, 0x1A, 0x0A];

    private static ReadOnlySpan<byte> PngEnd => [0, 0, 0, 0, (byte)'I', (byte)'E', (byte)'N', (byte)'D', 0xAE, 0x42, 0x60, 0x82];

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

    /// <summary>Decodes the image file <paramref name="file"/>; <paramref name="name"/> (its path) starts every error message.</summary>
    public static RgbImage Decode(byte[] file, string name)
    {
        ArgumentNullException.ThrowIfNull(file);
        UserError Fail(string problem) => new($"{name}: {problem}");
        if (file.Length == 0) throw Fail("the file is empty");

        using var codec = SKCodec.Create(new MemoryStream(file), out var opened);
        if (codec is null)
            throw Fail(opened == SKCodecResult.Unimplemented
                ? "not an image file this program reads (PNG, JPEG, WebP, BMP or GIF)"
                : $"damaged: the {(file.AsSpan().StartsWith(PngSignature) ? "PNG " : "")}header cannot be read ({Describe(opened)})");
        var (width, height) = (codec.Info.Width, codec.Info.Height);
        if (width < 1 || height < 1) throw Fail($"the image has size {width}x{height}; both sides must be at least 1");
        if (width > MaxSide || height > MaxSide || (long)width * height > MaxPixels)
            throw Fail($"the image is too large ({width}x{height}; at most {MaxSide} per side and {MaxPixels:N0} pixels)");
        // libpng decodes every row of a file cut off in its last chunks; a whole PNG has its IEND chunk.
        if (codec.EncodedFormat == SKEncodedImageFormat.Png && file.AsSpan().IndexOf(PngEnd) < 0)
            throw Fail("truncated: the PNG file ends before its IEND chunk");

        // Premultiplied alpha is colour composited over black; no colour space is given, so values are not converted.
        var info = new SKImageInfo(width, height, SKColorType.Rgba8888, SKAlphaType.Premul);
        using var bitmap = new SKBitmap(info);
        var decoded = codec.GetPixels(info, bitmap.GetPixels());
        if (decoded != SKCodecResult.Success)
            throw Fail($"damaged or truncated: the {codec.EncodedFormat.ToString().ToUpperInvariant()} image data cannot be decoded ({Describe(decoded)})");

        return SkiaPixels.ToImage(bitmap);
    }

    private static string Describe(SKCodecResult result) => result switch
    {
        SKCodecResult.IncompleteInput => "the data ends early or is corrupt",
        SKCodecResult.ErrorInInput => "the data holds an error",
        SKCodecResult.InvalidInput => "the data is not valid",
        _ => $"the decoder reports {result}",
    };
}
