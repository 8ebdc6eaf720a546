using SkiaSharp;

namespace QuantumRayTracing.Output;

/// <summary>
/// Lays images out in a labelled grid on white with SkiaSharp, for docs: each panel enlarged by a whole factor
/// (nearest neighbour, so every pixel stays a visible square) under its label. Rows may have different numbers of panels.
/// </summary>
public static class ImageMontage
{
    private const int Gap = 8;
    private const float TextSize = 16;

    public static RgbImage Grid(IReadOnlyList<IReadOnlyList<(RgbImage Image, string Label)>> rows, int scale)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(scale, 1);
        if (rows.Count == 0 || rows.Any(r => r.Count == 0)) throw new ArgumentException("a montage needs at least one panel in every row");
        using var font = new SKFont(SKTypeface.FromFamilyName(PlotImage.FontFamily), TextSize);
        using var ink = new SKPaint { Color = SKColors.Black, IsAntialias = true };
        var labelHeight = (int)Math.Ceiling(font.Spacing) + Gap / 2;
        // Every cell is as large as the largest panel (or its label), so columns line up.
        var cellWidth = rows.SelectMany(r => r).Max(p => Math.Max(p.Image.Width * scale, (int)Math.Ceiling(font.MeasureText(p.Label))));
        var cellHeight = rows.SelectMany(r => r).Max(p => p.Image.Height * scale) + labelHeight;
        var columns = rows.Max(r => r.Count);
        var (width, height) = (Gap + columns * (cellWidth + Gap), Gap + rows.Count * (cellHeight + Gap));

        var (surface, info) = SkiaPixels.Surface(width, height);
        using var _ = surface;
        var canvas = surface.Canvas;
        canvas.Clear(SKColors.White);
        for (var r = 0; r < rows.Count; r++)
            for (var c = 0; c < rows[r].Count; c++)
            {
                var (image, label) = rows[r][c];
                var (left, top) = (Gap + c * (cellWidth + Gap), Gap + r * (cellHeight + Gap));
                canvas.DrawText(label, left, top - font.Metrics.Ascent, font, ink);
                using var bitmap = SkiaPixels.ToBitmap(image);
                using var panel = SKImage.FromBitmap(bitmap);
                var target = SKRect.Create(left, top + labelHeight, image.Width * scale, image.Height * scale);
                canvas.DrawImage(panel, target, new SKSamplingOptions(SKFilterMode.Nearest));
            }
        return SkiaPixels.ToImage(surface, info);
    }
}
