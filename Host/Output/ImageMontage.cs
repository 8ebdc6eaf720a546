using QuantumRayTracing.Output.Plots;

namespace QuantumRayTracing.Output;

/// <summary>
/// Lays images out in a labelled grid on white, for docs: each panel enlarged by a whole factor (nearest neighbour,
/// so every pixel stays a visible square) under its label. Rows may have different numbers of panels.
/// </summary>
public static class ImageMontage
{
    private const int Gap = 8;
    private const int TextScale = 2;

    public static RgbImage Grid(IReadOnlyList<IReadOnlyList<(RgbImage Image, string Label)>> rows, int scale)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(scale, 1);
        if (rows.Count == 0 || rows.Any(r => r.Count == 0)) throw new ArgumentException("a montage needs at least one panel in every row");
        var labelHeight = BitmapFont.GlyphHeight * TextScale + Gap / 2;
        // Every cell is as large as the largest panel (or its label), so columns line up.
        var cellWidth = rows.SelectMany(r => r).Max(p => Math.Max(p.Image.Width * scale, BitmapFont.Measure(p.Label, TextScale).Width));
        var cellHeight = rows.SelectMany(r => r).Max(p => p.Image.Height * scale) + labelHeight;
        var columns = rows.Max(r => r.Count);
        var montage = new RgbImage(Gap + columns * (cellWidth + Gap), Gap + rows.Count * (cellHeight + Gap));
        new Canvas(montage).FillRect(0, 0, montage.Width, montage.Height, PlotColour.White);
        for (var r = 0; r < rows.Count; r++)
            for (var c = 0; c < rows[r].Count; c++)
            {
                var (image, label) = rows[r][c];
                var (left, top) = (Gap + c * (cellWidth + Gap), Gap + r * (cellHeight + Gap));
                BitmapFont.DrawText(montage, label, left, top, PlotColour.Black, TextScale);
                for (var y = 0; y < image.Height * scale; y++)
                    for (var x = 0; x < image.Width * scale; x++)
                    {
                        var (red, green, blue) = image.GetPixel(x / scale, y / scale);
                        montage.SetPixel(left + x, top + labelHeight + y, red, green, blue);
                    }
            }
        return montage;
    }
}
