namespace QuantumRayTracing.Output;

/// <summary>An 8-bit RGB image, pixels stored row-major, three bytes (R, G, B) per pixel, top row first.</summary>
public sealed class RgbImage
{
    private readonly byte[] _pixels;

    /// <summary>A black image of the given size.</summary>
    /// <exception cref="ArgumentOutOfRangeException">Width or height is less than 1, or the image would not fit in one array.</exception>
    public RgbImage(int width, int height)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(width, 1);
        ArgumentOutOfRangeException.ThrowIfLessThan(height, 1);
        // Compared without multiplying by 3: int.MaxValue squared times 3 overflows even a long, and the
        // int product would silently wrap to a tiny array.
        if ((long)width * height > Array.MaxLength / 3)
            throw new ArgumentOutOfRangeException(nameof(width), $"{width}x{height} pixels do not fit in one array");
        Width = width;
        Height = height;
        _pixels = new byte[width * height * 3];
    }

    /// <summary>An image over <paramref name="pixels"/>, row-major R, G, B (as <see cref="Pixels"/> gives them), taken as they are.</summary>
    public static RgbImage FromPixels(int width, int height, byte[] pixels)
    {
        var image = new RgbImage(width, height);
        if (pixels.Length != image._pixels.Length) throw new ArgumentException($"{pixels.Length} bytes are not the {width}x{height} pixels' {image._pixels.Length}", nameof(pixels));
        pixels.CopyTo(image._pixels, 0);
        return image;
    }

    /// <summary>Number of columns, at least 1.</summary>
    public int Width { get; }

    /// <summary>Number of rows, at least 1.</summary>
    public int Height { get; }

    /// <summary>All pixels, row-major, R, G, B per pixel; row <c>y</c> starts at <c>y * Width * 3</c>.</summary>
    public ReadOnlySpan<byte> Pixels => _pixels;

    /// <summary>The colour at column <paramref name="x"/>, row <paramref name="y"/> (row 0 is the top).</summary>
    public (byte R, byte G, byte B) GetPixel(int x, int y)
    {
        var i = Offset(x, y);
        return (_pixels[i], _pixels[i + 1], _pixels[i + 2]);
    }

    /// <summary>Sets the colour at column <paramref name="x"/>, row <paramref name="y"/> (row 0 is the top).</summary>
    public void SetPixel(int x, int y, byte r, byte g, byte b)
    {
        var i = Offset(x, y);
        _pixels[i] = r;
        _pixels[i + 1] = g;
        _pixels[i + 2] = b;
    }

    /// <summary>
    /// An image from a colour function with channels nominally in [0, 1]. Each channel is clamped to [0, 1]
    /// (NaN becomes 0) and quantised as <c>Math.Round(v * 255, MidpointRounding.AwayFromZero)</c>.
    /// No gamma or sRGB transfer is applied: the values are written as they are. Rows are filled on all cores, so
    /// <paramref name="colour"/> must only read shared state.
    /// </summary>
    public static RgbImage FromLinear(int width, int height, Func<int, int, (double R, double G, double B)> colour)
    {
        ArgumentNullException.ThrowIfNull(colour);
        var image = new RgbImage(width, height);
        // Rows on all cores: each pixel is written once, from its own colour.
        Parallel.For(0, height, y =>
        {
            for (var x = 0; x < width; x++)
            {
                var (r, g, b) = colour(x, y);
                image.SetPixel(x, y, Quantise(r), Quantise(g), Quantise(b));
            }
        });
        return image;
    }

    private static byte Quantise(double value)
    {
        // Math.Clamp passes NaN through, and casting NaN to byte is unspecified: make it black.
        if (double.IsNaN(value)) return 0;
        return (byte)Math.Round(Math.Clamp(value, 0.0, 1.0) * 255, MidpointRounding.AwayFromZero);
    }

    private int Offset(int x, int y)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(x);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(x, Width);
        ArgumentOutOfRangeException.ThrowIfNegative(y);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(y, Height);
        return (y * Width + x) * 3;
    }
}
