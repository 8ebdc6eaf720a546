namespace QuantumRayTracing.Output.Plots;

/// <summary>
/// Pixel drawing on an <see cref="RgbImage"/>: crisp rectangles and rules, anti-aliased lines and filled shapes.
/// Everything is limited to <see cref="Clip"/>, so callers can draw data without checking bounds.
/// </summary>
internal sealed class Canvas
{
    // Sub-samples per side when estimating how much of a pixel a shape covers.
    private const int Subsamples = 4;

    private readonly PixelRect _bounds;
    private PixelRect _clip;

    public Canvas(RgbImage image)
    {
        Image = image;
        _bounds = new PixelRect(0, 0, image.Width, image.Height);
        _clip = _bounds;
    }

    public RgbImage Image { get; }

    /// <summary>The pixels drawing may change; always inside the image.</summary>
    public PixelRect Clip
    {
        get => _clip;
        set => _clip = value.Intersect(_bounds);
    }

    public void FillRect(int left, int top, int width, int height, PlotColour colour)
    {
        var area = new PixelRect(left, top, Math.Max(0, width), Math.Max(0, height)).Intersect(_clip);
        for (var y = area.Top; y < area.Bottom; y++)
            for (var x = area.Left; x < area.Right; x++)
                Image.SetPixel(x, y, colour.R, colour.G, colour.B);
    }

    /// <summary>A one-pixel outline just inside the rectangle.</summary>
    public void StrokeRect(PixelRect rect, PlotColour colour)
    {
        HorizontalRule(rect.Left, rect.Right - 1, rect.Top, colour);
        HorizontalRule(rect.Left, rect.Right - 1, rect.Bottom - 1, colour);
        VerticalRule(rect.Left, rect.Top, rect.Bottom - 1, colour);
        VerticalRule(rect.Right - 1, rect.Top, rect.Bottom - 1, colour);
    }

    /// <summary>Row <paramref name="y"/> from column <paramref name="x0"/> to <paramref name="x1"/>, both included.</summary>
    public void HorizontalRule(int x0, int x1, int y, PlotColour colour) =>
        FillRect(Math.Min(x0, x1), y, Math.Abs(x1 - x0) + 1, 1, colour);

    /// <summary>Column <paramref name="x"/> from row <paramref name="y0"/> to <paramref name="y1"/>, both included.</summary>
    public void VerticalRule(int x, int y0, int y1, PlotColour colour) =>
        FillRect(x, Math.Min(y0, y1), 1, Math.Abs(y1 - y0) + 1, colour);

    /// <summary>
    /// A straight line with round ends between two points in continuous pixel coordinates. Each pixel takes the
    /// colour in proportion to how much of it lies within <paramref name="width"/> / 2 of the segment, which keeps
    /// slanted lines smooth and as heavy as straight ones. Non-finite end points draw nothing.
    /// </summary>
    public void Line(double x0, double y0, double x1, double y1, double width, PlotColour colour)
    {
        if (!double.IsFinite(x0) || !double.IsFinite(y0) || !double.IsFinite(x1) || !double.IsFinite(y1) || _clip.Width == 0 || _clip.Height == 0)
            return;
        var half = width / 2;
        // Cut the segment to the clip rectangle (plus the line's reach) first: distances to a segment whose ends
        // lie far outside, such as a point mapped from a huge value, would overflow.
        var margin = half + 2;
        if (!ClipSegment(ref x0, ref y0, ref x1, ref y1, _clip.Left - margin, _clip.Top - margin, _clip.Right + margin, _clip.Bottom + margin))
            return;

        // Walk the longer direction ("major") one pixel at a time and cover a band across it, so each pixel is
        // visited once and a long line costs its length, not its bounding box.
        var steep = Math.Abs(y1 - y0) > Math.Abs(x1 - x0);
        var (u0, v0, u1, v1) = steep ? (y0, x0, y1, x1) : (x0, y0, x1, y1);
        if (u0 > u1) (u0, v0, u1, v1) = (u1, v1, u0, v0);
        var slope = u1 > u0 ? (v1 - v0) / (u1 - u0) : 0;
        // Pixels within half + 0.5 of the line can be this far from it across the major direction.
        var reach = (half + 0.5) * Math.Sqrt(1 + slope * slope) + 0.5;

        var (majorMin, majorMax) = steep ? (_clip.Top, _clip.Bottom - 1) : (_clip.Left, _clip.Right - 1);
        var (minorMin, minorMax) = steep ? (_clip.Left, _clip.Right - 1) : (_clip.Top, _clip.Bottom - 1);
        var first = Bound(Math.Floor(u0 - half - 1), majorMin, majorMax + 1);
        var last = Bound(Math.Ceiling(u1 + half + 1), majorMin - 1, majorMax);
        for (var u = first; u <= last; u++)
        {
            var centre = v0 + (Math.Clamp(u + 0.5, u0, u1) - u0) * slope;
            var from = Bound(Math.Floor(centre - reach), minorMin, minorMax + 1);
            var to = Bound(Math.Floor(centre + reach), minorMin - 1, minorMax);
            for (var v = from; v <= to; v++)
            {
                var (x, y) = steep ? (v, u) : (u, v);
                var distance = DistanceToSegment(x + 0.5, y + 0.5, x0, y0, x1, y1);
                Blend(x, y, colour, Math.Clamp(half + 0.5 - distance, 0, 1));
            }
        }
    }

    /// <summary>
    /// Fills the marker <paramref name="shape"/> of radius <paramref name="radius"/> centred at
    /// (<paramref name="cx"/>, <paramref name="cy"/>), edge pixels blended by the share of sub-samples inside.
    /// </summary>
    public void Marker(MarkerShape shape, double cx, double cy, double radius, PlotColour colour)
    {
        if (!double.IsFinite(cx) || !double.IsFinite(cy)) return;
        // Every shape stays within 1.5 radii of its centre.
        var extent = 1.5 * radius + 1;
        var left = Bound(Math.Floor(cx - extent), _clip.Left, _clip.Right);
        var right = Bound(Math.Ceiling(cx + extent), _clip.Left - 1, _clip.Right - 1);
        var top = Bound(Math.Floor(cy - extent), _clip.Top, _clip.Bottom);
        var bottom = Bound(Math.Ceiling(cy + extent), _clip.Top - 1, _clip.Bottom - 1);
        for (var y = top; y <= bottom; y++)
            for (var x = left; x <= right; x++)
            {
                var inside = 0;
                for (var sy = 0; sy < Subsamples; sy++)
                    for (var sx = 0; sx < Subsamples; sx++)
                    {
                        var dx = x + (sx + 0.5) / Subsamples - cx;
                        var dy = y + (sy + 0.5) / Subsamples - cy;
                        if (shape.Contains(dx, dy, radius)) inside++;
                    }
                Blend(x, y, colour, (double)inside / (Subsamples * Subsamples));
            }
    }

    /// <summary>Mixes <paramref name="colour"/> into pixel (x, y) with weight <paramref name="alpha"/> in [0, 1].</summary>
    public void Blend(int x, int y, PlotColour colour, double alpha)
    {
        if (!(alpha > 0) || !_clip.Contains(x, y)) return;
        if (alpha >= 1)
        {
            Image.SetPixel(x, y, colour.R, colour.G, colour.B);
            return;
        }
        var (r, g, b) = Image.GetPixel(x, y);
        Image.SetPixel(x, y, Mix(r, colour.R, alpha), Mix(g, colour.G, alpha), Mix(b, colour.B, alpha));
    }

    /// <summary>
    /// Liang-Barsky clipping of a segment to a rectangle; false when nothing of it is inside. The segment is
    /// walked from whichever of its ends or its midpoint lies nearest the rectangle, in steps of half its length,
    /// so ends far outside (even at opposite ends of the double range) neither overflow nor swamp the result.
    /// </summary>
    private static bool ClipSegment(ref double x0, ref double y0, ref double x1, ref double y1,
        double left, double top, double right, double bottom)
    {
        double dx = x1 / 2 - x0 / 2, dy = y1 / 2 - y0 / 2;
        double cx = left / 2 + right / 2, cy = top / 2 + bottom / 2;
        var (rx, ry, enter, leave) = (x0, y0, 0.0, 2.0);
        foreach (var (px, py, from) in new[] { (x0 / 2 + x1 / 2, y0 / 2 + y1 / 2, -1.0), (x1, y1, -2.0) })
            if (Math.Max(Math.Abs(px - cx), Math.Abs(py - cy)) < Math.Max(Math.Abs(rx - cx), Math.Abs(ry - cy)))
                (rx, ry, enter, leave) = (px, py, from, from + 2);

        Span<(double P, double Q)> edges = [(-dx, rx - left), (dx, right - rx), (-dy, ry - top), (dy, bottom - ry)];
        foreach (var (p, q) in edges)
        {
            if (p == 0)
            {
                if (q < 0) return false;
                continue;
            }
            var u = q / p;
            if (p < 0) enter = Math.Max(enter, u);
            else leave = Math.Min(leave, u);
            if (enter > leave) return false;
        }
        (x0, y0) = (rx + enter * dx, ry + enter * dy);
        (x1, y1) = (rx + leave * dx, ry + leave * dy);
        return true;
    }

    // Far-off coordinates (a point mapped from a huge value) are clamped before the cast, so the loops stay
    // within the clip rectangle and an empty range comes out as first > last.
    private static int Bound(double value, int min, int max) => (int)Math.Clamp(value, min, max);

    private static byte Mix(byte under, byte over, double alpha) =>
        (byte)Math.Round(under + (over - under) * alpha, MidpointRounding.AwayFromZero);

    private static double DistanceToSegment(double px, double py, double x0, double y0, double x1, double y1)
    {
        double dx = x1 - x0, dy = y1 - y0;
        var lengthSquared = dx * dx + dy * dy;
        var t = lengthSquared > 0 ? Math.Clamp(((px - x0) * dx + (py - y0) * dy) / lengthSquared, 0, 1) : 0;
        double ex = px - (x0 + t * dx), ey = py - (y0 + t * dy);
        return Math.Sqrt(ex * ex + ey * ey);
    }
}
