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
