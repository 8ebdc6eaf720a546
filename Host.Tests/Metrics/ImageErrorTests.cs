using QuantumRayTracing.Metrics;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Tests.Metrics;

/// <summary>NRMSE, #Dpix and %Dpix (docs/conventions.md) and the difference picture, on images small enough to do by hand.</summary>
public class ImageErrorTests
{
    private static RgbImage Image(params (byte R, byte G, byte B)[] pixels)
    {
        var image = new RgbImage(pixels.Length, 1);
        for (var x = 0; x < pixels.Length; x++) image.SetPixel(x, 0, pixels[x].R, pixels[x].G, pixels[x].B);
        return image;
    }

    [Fact]
    public void NrmseIsNormalisedByTheReferenceRange()
    {
        // Reference channels 10, 20, 30, 110, 20, 30: range 110 − 10 = 100. Differences +3 and −4 in pixel 0:
        // squares 9 + 16 = 25 over 6 channel values, RMSE = sqrt(25 / 6), NRMSE = sqrt(25 / 6) / 100.
        var reference = Image((10, 20, 30), (110, 20, 30));
        var image = Image((13, 20, 26), (110, 20, 30));
        var error = ImageError.Between(image, reference);
        Assert.Equal(Math.Sqrt(25.0 / 6) / 100, error.Nrmse, 12);
        Assert.Equal(1, error.DifferentPixels);
        Assert.Equal(0.5, error.DifferentShare);
    }

    [Fact]
    public void RangeComesFromTheReferenceNotTheImage()
    {
        // Swapping roles: reference channels 13, 20, 26, 110, 20, 30 have range 110 − 13 = 97.
        var error = ImageError.Between(Image((10, 20, 30), (110, 20, 30)), Image((13, 20, 26), (110, 20, 30)));
        Assert.Equal(Math.Sqrt(25.0 / 6) / 97, error.Nrmse, 12);
    }

    [Fact]
    public void FlatReferenceUsesTheFullScale()
    {
        // Every reference channel is 50: no range, so 255. One channel off by 6: RMSE = sqrt(36 / 6) = sqrt 6.
        var reference = Image((50, 50, 50), (50, 50, 50));
        var error = ImageError.Between(Image((50, 50, 50), (50, 50, 56)), reference);
        Assert.Equal(Math.Sqrt(6) / 255, error.Nrmse, 12);
        Assert.Equal((1, 0.5), (error.DifferentPixels, error.DifferentShare));
    }

    [Fact]
    public void EveryPixelDifferent()
    {
        // Range 200 − 0; each of the 6 channels off by 2: RMSE 2, NRMSE 0.01; both pixels differ.
        var error = ImageError.Between(Image((2, 2, 2), (198, 198, 198)), Image((0, 0, 0), (200, 200, 200)));
        Assert.Equal(0.01, error.Nrmse, 12);
        Assert.Equal((2, 1.0), (error.DifferentPixels, error.DifferentShare));
    }

    [Fact]
    public void IdenticalImagesHaveNoError()
    {
        var image = Image((1, 2, 3), (200, 100, 0));
        Assert.Equal(new ImageError(0, 0, 0), ImageError.Between(image, Image((1, 2, 3), (200, 100, 0))));
    }

    [Fact]
    public void SizesMustMatch() =>
        Assert.Throws<ArgumentException>(() => ImageError.Between(Image((1, 1, 1)), Image((1, 1, 1), (1, 1, 1))));

    [Fact]
    public void DifferenceMarksExactlyTheDifferingPixels()
    {
        // Pixel 1 differs in one channel only, pixel 3 in all three; the others keep the reference / 4 (integer).
        var reference = Image((100, 50, 3), (40, 80, 120), (255, 255, 255), (8, 9, 10));
        var image = Image((100, 50, 3), (40, 81, 120), (255, 255, 255), (0, 0, 0));
        var difference = DifferenceImage.Of(image, reference);
        Assert.Equal(((byte)25, (byte)12, (byte)0), difference.GetPixel(0, 0));
        Assert.Equal(((byte)255, (byte)0, (byte)0), difference.GetPixel(1, 0));
        Assert.Equal(((byte)63, (byte)63, (byte)63), difference.GetPixel(2, 0));
        Assert.Equal(((byte)255, (byte)0, (byte)0), difference.GetPixel(3, 0));
        Assert.Equal(2, ImageError.Between(image, reference).DifferentPixels);
    }
}
