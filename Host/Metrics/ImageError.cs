using QuantumRayTracing.Output;

namespace QuantumRayTracing.Metrics;

/// <summary>
/// How far an image is from its reference (docs/conventions.md): NRMSE over all 8-bit channel values,
/// normalised by the reference's value range (max − min over its channels), and #Dpix / %Dpix, the
/// pixels whose 8-bit RGB differs.
/// </summary>
public readonly record struct ImageError(double Nrmse, int DifferentPixels, double DifferentShare)
{
    public static ImageError Between(RgbImage image, RgbImage reference)
    {
        if (image.Width != reference.Width || image.Height != reference.Height)
            throw new ArgumentException($"image is {image.Width}x{image.Height}, reference {reference.Width}x{reference.Height}");
        var a = image.Pixels;
        var b = reference.Pixels;
        double squares = 0;
        int min = 255, max = 0, different = 0;
        for (var i = 0; i < a.Length; i += 3)
        {
            var differs = false;
            for (var c = i; c < i + 3; c++)
            {
                var d = a[c] - b[c];
                squares += d * d;
                differs |= d != 0;
                min = Math.Min(min, b[c]);
                max = Math.Max(max, b[c]);
            }
            if (differs) different++;
        }
        var rmse = Math.Sqrt(squares / a.Length);
        // A flat reference has no range: any error is then reported against the full 8-bit scale.
        var range = max > min ? max - min : 255;
        var pixels = a.Length / 3;
        return new ImageError(rmse / range, different, (double)different / pixels);
    }
}
