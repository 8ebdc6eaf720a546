namespace QuantumRayTracing.Output.Plots;

/// <summary>
/// A rectangle of whole pixels: columns <see cref="Left"/> to <see cref="Right"/> - 1 and rows
/// <see cref="Top"/> to <see cref="Bottom"/> - 1. In continuous pixel coordinates it spans
/// [Left, Right) x [Top, Bottom), pixel (x, y) having its centre at (x + 0.5, y + 0.5).
/// </summary>
public readonly record struct PixelRect(int Left, int Top, int Width, int Height)
{
    /// <summary>One past the last column.</summary>
    public int Right => Left + Width;

    /// <summary>One past the last row.</summary>
    public int Bottom => Top + Height;

    /// <summary>Whether pixel (<paramref name="x"/>, <paramref name="y"/>) lies inside.</summary>
    public bool Contains(int x, int y) => x >= Left && x < Right && y >= Top && y < Bottom;

    /// <summary>The pixels in both rectangles (empty, with zero size, when they do not overlap).</summary>
    public PixelRect Intersect(PixelRect other)
    {
        var left = Math.Max(Left, other.Left);
        var top = Math.Max(Top, other.Top);
        var right = Math.Min(Right, other.Right);
        var bottom = Math.Min(Bottom, other.Bottom);
        return new PixelRect(left, top, Math.Max(0, right - left), Math.Max(0, bottom - top));
    }
}
