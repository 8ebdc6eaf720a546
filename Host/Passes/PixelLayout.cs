namespace QuantumRayTracing.Passes;

/// <summary>
/// Where a pass's rays sit on the image, for neighbour gathering: ray i belongs to a pixel and a
/// channel (for shadow rays, which light and which surface point of the pixel), and its neighbours are
/// the rays of the same channel at the 4 von Neumann neighbouring pixels.
/// </summary>
/// <remarks>
/// The rays are indexed by pixel (each pixel's rays listed together, an offset per pixel): a lookup scans the few rays
/// of one pixel, and the index takes a few bytes per ray and pixel rather than a hash entry per ray.
/// </remarks>
public sealed class PixelLayout
{
    private readonly int _width;
    private readonly int _height;
    private readonly int[] _pixelOf;
    private readonly int[] _channelOf;
    private readonly int[] _firstOfPixel;
    private readonly int[] _byPixel;

    public PixelLayout(int width, int height, IReadOnlyList<int> pixelOfRay, IReadOnlyList<int>? channelOfRay = null)
    {
        _width = width;
        _height = height;
        _pixelOf = ReadAll(pixelOfRay);
        _channelOf = channelOfRay is null ? new int[_pixelOf.Length] : ReadAll(channelOfRay);
        _firstOfPixel = new int[width * height + 1];
        foreach (var pixel in _pixelOf) _firstOfPixel[pixel + 1]++;
        for (var pixel = 0; pixel < width * height; pixel++) _firstOfPixel[pixel + 1] += _firstOfPixel[pixel];
        _byPixel = new int[_pixelOf.Length];
        var next = _firstOfPixel[..^1];
        for (var i = 0; i < _pixelOf.Length; i++) _byPixel[next[_pixelOf[i]]++] = i;
    }

    // Every item by its index, on all cores: a shadow pass's pixels and channels are computed on each read.
    private static int[] ReadAll(IReadOnlyList<int> items)
    {
        var all = new int[items.Count];
        if (all.Length == 0) return all;
        Parallel.ForEach(System.Collections.Concurrent.Partitioner.Create(0, all.Length, 1 << 14), range =>
        {
            for (var i = range.Item1; i < range.Item2; i++) all[i] = items[i];
        });
        return all;
    }

    // The ray of channel `channel` at `pixel` (the last listed, should two share both), or −1.
    private int RayAt(int pixel, int channel)
    {
        for (var k = _firstOfPixel[pixel + 1] - 1; k >= _firstOfPixel[pixel]; k--)
            if (_channelOf[_byPixel[k]] == channel) return _byPixel[k];
        return -1;
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
        var (y, x) = Math.DivRem(_pixelOf[ray], _width);
        return LevelAt(x, y, levels);
    }

    // Both coordinates are multiples of 2^k exactly for k up to the trailing zeros they share (every k for the origin).
    private static int LevelAt(int x, int y, int levels) => Math.Min(levels, System.Numerics.BitOperations.TrailingZeroCount(x | y));

    /// <summary>
    /// The rays of the same channel on the next coarser lattice around ray <paramref name="ray"/>: the
    /// pixels at offsets −s, 0, s (s = 2^level) in x and y whose coordinates are multiples of 2s.
    /// </summary>
    public IEnumerable<int> CoarserNeighbours(int ray, int levels)
    {
        Span<int> found = stackalloc int[MostCoarserNeighbours];
        return found[..CoarserNeighbours(ray, levels, found)].ToArray();
    }

    /// <summary>At most this many coarser lattice neighbours: the corners of a lattice cell.</summary>
    public const int MostCoarserNeighbours = 4;

    /// <summary>
    /// <see cref="CoarserNeighbours(int, int)"/> into <paramref name="into"/> (at least <see cref="MostCoarserNeighbours"/>
    /// long), in the same order, without allocating: returns how many.
    /// </summary>
    public int CoarserNeighbours(int ray, int levels, Span<int> into)
    {
        var count = 0;
        var (y, x) = Math.DivRem(_pixelOf[ray], _width);
        var step = 1 << LevelAt(x, y, levels);
        // A coordinate, a multiple of step, is on the coarser lattice when its step bit is clear: then it stays (offset 0),
        // otherwise both neighbours at −step and +step are on it. Offsets ascend, y outer, as the corners of the cell.
        var (dyFrom, dyStep) = (y & step) != 0 ? (-step, 2 * step) : (0, 1);
        var (dxFrom, dxStep) = (x & step) != 0 ? (-step, 2 * step) : (0, 1);
        for (var dy = dyFrom; dy <= -dyFrom; dy += dyStep)
            for (var dx = dxFrom; dx <= -dxFrom; dx += dxStep)
            {
                var (nx, ny) = (x + dx, y + dy);
                if ((dx, dy) == (0, 0) || nx < 0 || ny < 0 || nx >= _width || ny >= _height) continue;
                if (RayAt(ny * _width + nx, _channelOf[ray]) is var neighbour and >= 0) into[count++] = neighbour;
            }
        return count;
    }

    /// <summary>
    /// How many coarser lattice neighbours ray <paramref name="ray"/> has away from the image's border:
    /// 2 on a lattice edge's midpoint, 4 at a cell's centre. Fewer in <see cref="CoarserNeighbours(int, int)"/>
    /// means the border cut some off or their pixels have no ray of this channel.
    /// </summary>
    public int CoarserNeighbourSlots(int ray, int levels)
    {
        var (y, x) = Math.DivRem(_pixelOf[ray], _width);
        var step = 1 << LevelAt(x, y, levels);
        return ((x & step) != 0 ? 2 : 1) * ((y & step) != 0 ? 2 : 1);
    }

    /// <summary>The rays of the same channel at the pixels left, right, above and below ray <paramref name="ray"/>'s.</summary>
    /// <remarks>Into <paramref name="into"/> (at least 4 long) without allocating: returns how many.</remarks>
    public int Neighbours(int ray, Span<int> into)
    {
        var count = 0;
        var (pixel, channel) = (_pixelOf[ray], _channelOf[ray]);
        var (y, x) = Math.DivRem(pixel, _width);
        if (x > 0 && RayAt(pixel - 1, channel) is var left and >= 0) into[count++] = left;
        if (x < _width - 1 && RayAt(pixel + 1, channel) is var right and >= 0) into[count++] = right;
        if (y > 0 && RayAt(pixel - _width, channel) is var up and >= 0) into[count++] = up;
        if (y < _height - 1 && RayAt(pixel + _width, channel) is var down and >= 0) into[count++] = down;
        return count;
    }
}
