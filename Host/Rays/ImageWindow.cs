namespace QuantumRayTracing.Rays;

/// <summary>
/// A rectangle of an image's pixels, <see cref="Width"/> x <see cref="Height"/> from (<see cref="X"/>, <see cref="Y"/>) in an
/// image of <see cref="FullWidth"/> x <see cref="FullHeight"/>: the pixels a tile renders, its camera rays those of the whole image.
/// </summary>
public readonly record struct ImageWindow(int X, int Y, int Width, int Height, int FullWidth, int FullHeight)
{
    /// <summary>The whole image.</summary>
    public static ImageWindow Whole(int width, int height) => new(0, 0, width, height, width, height);

    public long Pixels => (long)Width * Height;
}
