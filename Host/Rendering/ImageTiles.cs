using QuantumRayTracing.Rays;

namespace QuantumRayTracing.Rendering;

/// <summary>One tile of a tiled render: the pixels it owns (<see cref="Interior"/>) and those it traces (<see cref="Traced"/>: its interior and a border).</summary>
public sealed record ImageTile(int Index, ImageWindow Interior, ImageWindow Traced);

/// <summary>
/// An image cut into square tiles of <c>size</c> pixels, row by row, each traced with a border of <c>border</c> pixels
/// (clipped at the image's edge), so that a tile's own pixels have every neighbour the lattice and neighbour gathering read.
/// With size and border multiples of the coarsest lattice step, a traced window starts on that step, and every pixel keeps
/// its lattice level (the trailing zero bits of its coordinates).
/// </summary>
public static class ImageTiles
{
    public static IReadOnlyList<ImageTile> Of(int width, int height, int size, int border)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(size, 1);
        ArgumentOutOfRangeException.ThrowIfNegative(border);
        var tiles = new List<ImageTile>();
        for (var y = 0; y < height; y += size)
            for (var x = 0; x < width; x += size)
            {
                var (w, h) = (Math.Min(size, width - x), Math.Min(size, height - y));
                var (left, top) = (Math.Max(0, x - border), Math.Max(0, y - border));
                var (right, bottom) = (Math.Min(width, x + w + border), Math.Min(height, y + h + border));
                tiles.Add(new ImageTile(tiles.Count, new ImageWindow(x, y, w, h, width, height),
                    new ImageWindow(left, top, right - left, bottom - top, width, height)));
            }
        return tiles;
    }
}
