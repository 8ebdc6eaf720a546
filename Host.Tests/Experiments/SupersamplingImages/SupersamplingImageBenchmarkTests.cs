using QuantumRayTracing.Experiments;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Tests.Experiments;

public class SupersamplingImageBenchmarkTests
{
    [Fact]
    public void ErrorInTheLeastConfidentPixels()
    {
        double[] confidence = [0.4, 0.1, 0.3, 0.2];
        double[] errors = [1, 4, 2, 3];
        Assert.Equal(0.4, SupersamplingImageBenchmark.ErrorInLeastConfident(confidence, errors, 0.25), 12);
        Assert.Equal(0.7, SupersamplingImageBenchmark.ErrorInLeastConfident(confidence, errors, 0.5), 12);
        Assert.Equal(1, SupersamplingImageBenchmark.ErrorInLeastConfident(confidence, errors, 1), 12);
        // Two pixels tie at the cut: each counts half.
        Assert.Equal(0.25, SupersamplingImageBenchmark.ErrorInLeastConfident([0.1, 0.1, 0.5, 0.5], [2, 0, 1, 1], 0.25), 12);
    }

    [Fact]
    public void ConfidenceBinsCountEveryPixelOnce()
    {
        double[] confidence = [0, 0.49, 0.5, 0.99, 1];
        double[] errors = [3, 1, 0, 0, 2];
        var bins = SupersamplingImageBenchmark.ByConfidence(confidence, errors, [0, 0.5, 1]);
        Assert.Equal([2, 3], bins.Select(b => b.Pixels));
        Assert.Equal(2, bins[0].MeanError, 12);
        Assert.Equal(0, bins[0].ExactShare);
        Assert.Equal(2.0 / 3, bins[1].MeanError, 12);
        Assert.Equal(2.0 / 3, bins[1].ExactShare, 12);
    }

    [Fact]
    public void BlackAndWhiteThresholdsLuminanceAtHalf()
    {
        var image = new RgbImage(3, 1);
        image.SetPixel(0, 0, 0, 255, 0);   // luminance 0.7152: white
        image.SetPixel(1, 0, 255, 0, 255); // 0.2126 + 0.0722: black
        image.SetPixel(2, 0, 128, 128, 128);
        var bw = SupersamplingImageBenchmark.BlackAndWhite(image);
        Assert.Equal([255, 255, 255, 0, 0, 0, 255, 255, 255], bw.Pixels.ToArray());
    }
}
