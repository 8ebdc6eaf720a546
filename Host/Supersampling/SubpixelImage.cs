using QuantumRayTracing.Estimation;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Supersampling;

/// <summary>
/// An image seen as s x s subpixels per output pixel: output pixel (x, y) covers the input block starting at
/// (s·x, s·y). Each channel's subpixel values are the 8-bit values / 255, and its target is their exact mean.
/// Values are read on demand, so a large input costs no more memory than the image itself.
/// </summary>
public sealed class SubpixelImage
{
    /// <param name="image">The input; both sides must be multiples of <paramref name="side"/> (the caller reports otherwise).</param>
    /// <param name="side">s, subpixels per side of an output pixel.</param>
    public SubpixelImage(RgbImage image, int side)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(side, 1);
        if (image.Width % side != 0 || image.Height % side != 0)
            throw new ArgumentException($"{image.Width}x{image.Height} is not a multiple of {side}");
        Image = image;
        Side = side;
        IsGrey = CheckGrey(image);
    }

    public RgbImage Image { get; }

    /// <summary>s: the output pixel covers s x s input pixels.</summary>
    public int Side { get; }

    /// <summary>N = s², the subpixels per output pixel.</summary>
    public int Count => Side * Side;

    public int Width => Image.Width / Side;

    public int Height => Image.Height / Side;

    public int Pixels => Width * Height;

    /// <summary>R = G = B in every input pixel: one channel carries the whole image.</summary>
    public bool IsGrey { get; }

    /// <summary>The 8-bit subpixel values of output pixel <paramref name="pixel"/> (row-major) in channel <paramref name="channel"/> (0 R, 1 G, 2 B), row by row.</summary>
    public byte[] Levels(int pixel, int channel)
    {
        var (px, py) = (pixel % Width, pixel / Width);
        var levels = new byte[Count];
        var pixels = Image.Pixels;
        for (var dy = 0; dy < Side; dy++)
        {
            var row = ((py * Side + dy) * Image.Width + px * Side) * 3 + channel;
            for (var dx = 0; dx < Side; dx++) levels[dy * Side + dx] = pixels[row + 3 * dx];
        }
        return levels;
    }

    /// <summary>The subpixel values F(i) = level / 255 ∈ [0, 1].</summary>
    public double[] Values(int pixel, int channel) => Levels(pixel, channel).Select(l => l / 255.0).ToArray();

    /// <summary>The target: the exact mean of the subpixel values, from the integer sum.</summary>
    public double Mean(int pixel, int channel) => Levels(pixel, channel).Sum(l => (int)l) / (255.0 * Count);

    /// <summary>The ideal supersampled image: every pixel the exact mean, quantised as every output is.</summary>
    public RgbImage Ideal() => RgbImage.FromLinear(Width, Height, (x, y) =>
    {
        var p = y * Width + x;
        return (Mean(p, 0), Mean(p, 1), Mean(p, 2));
    });

    private static bool CheckGrey(RgbImage image)
    {
        var pixels = image.Pixels;
        for (var i = 0; i < pixels.Length; i += 3)
            if (pixels[i] != pixels[i + 1] || pixels[i] != pixels[i + 2]) return false;
        return true;
    }
}
