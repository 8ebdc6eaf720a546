using System.Text.Json.Serialization;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Metrics;

/// <summary>
/// A supersampled image against the exact average of its subpixels (docs/conventions.md): the mean absolute error over
/// pixels and channels in 8-bit levels between the output and the ideal image (each exact mean quantised the same
/// way), the same before quantisation (the estimator's own error, as a fraction of full scale), and the share of
/// pixels whose 8-bit RGB equals the ideal's. <see cref="PixelLevels"/>: each pixel's error, averaged over its channels.
/// </summary>
public sealed record SupersampleError(double MeanLevels, double EstimatorError, int ExactPixels, int Pixels, [property: JsonIgnore] double[] PixelLevels)
{
    /// <summary><see cref="MeanLevels"/> as a fraction of full scale.</summary>
    public double MeanFraction => MeanLevels / 255;

    public double ExactShare => (double)ExactPixels / Pixels;

    public static SupersampleError Of(SubpixelImage input, SupersampleResult result)
    {
        var ideal = input.Ideal().Pixels;
        var output = result.Image.Pixels;
        if (ideal.Length != output.Length) throw new ArgumentException("the result is not of this input's size");
        var (levels, estimator, exact) = (0L, 0.0, 0);
        var perPixel = new double[input.Pixels];
        for (var p = 0; p < input.Pixels; p++)
        {
            var pixel = 0;
            for (var c = 0; c < 3; c++)
            {
                pixel += Math.Abs(output[3 * p + c] - ideal[3 * p + c]);
                estimator += Math.Abs(result.Estimates[3 * p + c] - input.Mean(p, c));
            }
            levels += pixel;
            perPixel[p] = pixel / 3.0;
            if (pixel == 0) exact++;
        }
        return new SupersampleError((double)levels / output.Length, estimator / output.Length, exact, input.Pixels, perPixel);
    }
}
