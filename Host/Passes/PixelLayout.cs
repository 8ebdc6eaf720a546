namespace QuantumRayTracing.Passes;

/// <summary>
/// Where a pass's rays sit on the image, for neighbour gathering: ray i belongs to a pixel and a
/// channel (for shadow rays, which light and which surface point of the pixel), and its neighbours are
/// the rays of the same channel at the 4 von Neumann neighbouring pixels.
/// </summary>
public sealed class PixelLayout
{
    private readonly int _width;
    private readonly int _height;
    private readonly int[] _pixelOf;
    private readonly int[] _channelOf;
    private readonly Dictionary<(int Pixel, int Channel), int> _rayAt = [];

    public PixelLayout(int width, int height, IReadOnlyList<int> pixelOfRay, IReadOnlyList<int>? channelOfRay = null)
    {
        _width = width;
        _height = height;
        _pixelOf = [.. pixelOfRay];
        _channelOf = channelOfRay is null ? new int[_pixelOf.Length] : [.. channelOfRay];
        for (var i = 0; i < _pixelOf.Length; i++)
            _rayAt[(_pixelOf[i], _channelOf[i])] = i;
    }

    /// <summary>One ray per pixel, ray i at pixel i (the primary pass).</summary>
    public static PixelLayout Image(int width, int height) => new(width, height, Enumerable.Range(0, width * height).ToArray());

    public int Rays => _pixelOf.Length;

    /// <summary>
    /// The lattice level of ray <paramref name="ray"/>'s pixel, at most <paramref name="levels"/>: the
    /// largest k with both coordinates multiples of 2^k. Coarser levels are traced first.
    /// </summary>
    public int LatticeLevel(int ray, int levels)
    {
        var (x, y) = (_pixelOf[ray] % _width, _pixelOf[ray] / _width);
        var level = 0;
        while (level < levels && x % (2 << level) == 0 && y % (2 << level) == 0) level++;
        return level;
    }

    /// <summary>
    /// The rays of the same channel on the next coarser lattice around ray <paramref name="ray"/>: the
    /// pixels at offsets −s, 0, s (s = 2^level) in x and y whose coordinates are multiples of 2s.
    /// </summary>
    public IEnumerable<int> CoarserNeighbours(int ray, int levels)
    {
        var step = 1 << LatticeLevel(ray, levels);
        var (x, y) = (_pixelOf[ray] % _width, _pixelOf[ray] / _width);
        for (var dy = -step; dy <= step; dy += step)
            for (var dx = -step; dx <= step; dx += step)
            {
                var (nx, ny) = (x + dx, y + dy);
                if ((dx, dy) == (0, 0) || nx < 0 || ny < 0 || nx >= _width || ny >= _height || nx % (2 * step) != 0 || ny % (2 * step) != 0) continue;
                if (_rayAt.TryGetValue((ny * _width + nx, _channelOf[ray]), out var neighbour)) yield return neighbour;
            }
    }

    /// <summary>
    /// How many coarser lattice neighbours ray <paramref name="ray"/> has away from the image's border:
    /// 2 on a lattice edge's midpoint, 4 at a cell's centre. Fewer in <see cref="CoarserNeighbours"/>
    /// means the border cut some off or their pixels have no ray of this channel.
    /// </summary>
    public int CoarserNeighbourSlots(int ray, int levels)
    {
        var step = 1 << LatticeLevel(ray, levels);
        var (x, y) = (_pixelOf[ray] % _width / step, _pixelOf[ray] / _width / step);
        return (x % 2 == 1 ? 2 : 1) * (y % 2 == 1 ? 2 : 1);
    }

    /// <summary>The rays of the same channel at the pixels left, right, above and below ray <paramref name="ray"/>'s.</summary>
    public IEnumerable<int> Neighbours(int ray)
    {
        var (x, y) = (_pixelOf[ray] % _width, _pixelOf[ray] / _width);
        if (x > 0 && _rayAt.TryGetValue((_pixelOf[ray] - 1, _channelOf[ray]), out var left)) yield return left;
        if (x < _width - 1 && _rayAt.TryGetValue((_pixelOf[ray] + 1, _channelOf[ray]), out var right)) yield return right;
        if (y > 0 && _rayAt.TryGetValue((_pixelOf[ray] - _width, _channelOf[ray]), out var up)) yield return up;
        if (y < _height - 1 && _rayAt.TryGetValue((_pixelOf[ray] + _width, _channelOf[ray]), out var down)) yield return down;
    }
}
