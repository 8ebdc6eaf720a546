using SkiaSharp;

namespace QuantumRayTracing.Output;

/// <summary>
/// Moves pixels between <see cref="RgbImage"/> and SkiaSharp's 8-bit RGBA bitmaps, the one place where the two
/// layouts meet. Opaque both ways; a premultiplied bitmap's colour is its colour composited over black.
/// </summary>
internal static class SkiaPixels
{
    /// <summary>An opaque RGBA bitmap holding <paramref name="image"/> (the caller disposes it).</summary>
    public static SKBitmap ToBitmap(RgbImage image)
    {
        var bitmap = new SKBitmap(new SKImageInfo(image.Width, image.Height, SKColorType.Rgba8888, SKAlphaType.Opaque));
        var rgba = bitmap.GetPixelSpan();
        var rgb = image.Pixels;
        for (int i = 0, j = 0; i < rgb.Length; i += 3, j += 4)
        {
            rgba[j] = rgb[i];
            rgba[j + 1] = rgb[i + 1];
            rgba[j + 2] = rgb[i + 2];
            rgba[j + 3] = 255;
        }
        return bitmap;
    }

    /// <summary>The colours of an 8-bit RGBA <paramref name="bitmap"/>, its alpha dropped.</summary>
    public static RgbImage ToImage(SKBitmap bitmap)
    {
        if (bitmap.ColorType != SKColorType.Rgba8888) throw new ArgumentException($"expected RGBA 8888, not {bitmap.ColorType}", nameof(bitmap));
        var rgba = bitmap.GetPixelSpan();
        var image = new RgbImage(bitmap.Width, bitmap.Height);
        for (var y = 0; y < bitmap.Height; y++)
            for (var x = 0; x < bitmap.Width; x++)
            {
                var i = y * bitmap.RowBytes + x * 4;
                image.SetPixel(x, y, rgba[i], rgba[i + 1], rgba[i + 2]);
            }
        return image;
    }

    /// <summary>A drawing surface of the given size whose pixels <see cref="ToImage(SKSurface, SKImageInfo)"/> reads back.</summary>
    public static (SKSurface Surface, SKImageInfo Info) Surface(int width, int height)
    {
        var info = new SKImageInfo(width, height, SKColorType.Rgba8888, SKAlphaType.Premul);
        return (SKSurface.Create(info) ?? throw new ArgumentException($"a {width}x{height} drawing surface cannot be made"), info);
    }

    /// <summary>What was drawn on <paramref name="surface"/>.</summary>
    public static RgbImage ToImage(SKSurface surface, SKImageInfo info)
    {
        using var bitmap = new SKBitmap(info);
        if (!surface.ReadPixels(info, bitmap.GetPixels(), info.RowBytes, 0, 0))
            throw new InvalidOperationException("the drawn pixels could not be read back");
        return ToImage(bitmap);
    }
}
