using QuantumRayTracing.Estimation;
using QuantumRayTracing.Output;
using QuantumRayTracing.Passes;

namespace QuantumRayTracing.Supersampling;

/// <summary>
/// Supersamples an image: for each output pixel and colour channel, an estimator estimates the mean of
/// its s x s subpixel values with the engine. A grey input (R = G = B everywhere) is estimated in one channel and
/// copied to the others, so the output stays grey. Work goes to the engine in blocks of <see cref="BlockItems"/>
/// (pixel, channel) items in a fixed order, so the analytic engine's draws, and the output, depend only on the seed.
/// </summary>
public static class ImageSupersampler
{
    /// <summary>Items per estimator call: large enough to batch well on the simulator, small enough to report progress.</summary>
    public const int BlockItems = 2048;

    public static SupersampleResult Run(SubpixelImage input, IMeanEstimator estimator, ICoinEngine engine, IRenderProgress? progress = null)
    {
        var channels = input.IsGrey ? 1 : 3;
        var items = input.Pixels * channels;
        var estimates = new double[items];
        var confidence = estimator is BitPlaneQssEstimator ? new double[items] : null;
        for (var start = 0; start < items; start += BlockItems)
        {
            var count = Math.Min(BlockItems, items - start);
            var values = Enumerable.Range(start, count).Select(k => input.Values(k / channels, k % channels)).ToArray();
            if (estimator is BitPlaneQssEstimator planes)
            {
                var (e, c) = planes.Run(values, engine);
                e.CopyTo(estimates, start);
                c.CopyTo(confidence!, start);
            }
            else
            {
                var e = estimator.Estimate(values, engine);
                for (var k = 0; k < count; k++) estimates[start + k] = e[k];
            }
            progress?.Report("supersample", (double)(start + count) / items);
        }

        var all = new double[input.Pixels * 3];
        for (var k = 0; k < all.Length; k++) all[k] = estimates[k / 3 * channels + (channels == 1 ? 0 : k % 3)];
        var image = RgbImage.FromLinear(input.Width, input.Height, (x, y) =>
        {
            var p = 3 * (y * input.Width + x);
            return (all[p], all[p + 1], all[p + 2]);
        });
        double[]? pixelConfidence = null;
        RgbImage? map = null;
        if (confidence is not null)
        {
            pixelConfidence = new double[input.Pixels];
            for (var p = 0; p < input.Pixels; p++)
                for (var c = 0; c < channels; c++) pixelConfidence[p] += confidence[p * channels + c] / channels;
            map = RgbImage.FromLinear(input.Width, input.Height, (x, y) =>
            {
                var c = pixelConfidence[y * input.Width + x];
                return (c, c, c);
            });
        }
        return new SupersampleResult(all, image, pixelConfidence, map, estimator.Queries, channels, estimator.Name);
    }
}
