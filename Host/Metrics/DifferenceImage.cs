using QuantumRayTracing.Output;

namespace QuantumRayTracing.Metrics;

/// <summary>
/// A picture of where two images differ: the reference dimmed to a quarter, with every pixel whose
/// 8-bit RGB differs drawn bright red, so isolated wrong pixels are visible at a glance.
/// </summary>
public static class DifferenceImage
{
    public static RgbImage Of(RgbImage image, RgbImage reference)
    {
        if (image.Width != reference.Width || image.Height != reference.Height)
            throw new ArgumentException($"image is {image.Width}x{image.Height}, reference {reference.Width}x{reference.Height}");
        var difference = new RgbImage(image.Width, image.Height);
        for (var y = 0; y < image.Height; y++)
            for (var x = 0; x < image.Width; x++)
            {
                var a = image.GetPixel(x, y);
                var b = reference.GetPixel(x, y);
                if (a != b) difference.SetPixel(x, y, 255, 0, 0);
                else difference.SetPixel(x, y, (byte)(b.R / 4), (byte)(b.G / 4), (byte)(b.B / 4));
            }
        return difference;
    }
}
