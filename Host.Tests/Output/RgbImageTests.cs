using QuantumRayTracing.Output;

namespace QuantumRayTracing.Tests.Output;

public class RgbImageTests
{
    [Theory]
    [InlineData(0, 1)]
    [InlineData(1, 0)]
    [InlineData(-3, 4)]
    [InlineData(int.MaxValue, int.MaxValue)]
    public void RejectsSizesThatAreNotAnImage(int width, int height) =>
        Assert.Throws<ArgumentOutOfRangeException>(() => new RgbImage(width, height));

    [Fact]
    public void StoresPixelsRowMajor()
    {
        var image = new RgbImage(3, 2);
        image.SetPixel(2, 1, 7, 8, 9);
        Assert.Equal(((byte)7, (byte)8, (byte)9), image.GetPixel(2, 1));
        Assert.Equal((1 * 3 + 2) * 3, image.Pixels.IndexOf((byte)7));
        Assert.Equal(18, image.Pixels.Length);
    }

    [Theory]
    [InlineData(-1, 0)]
    [InlineData(3, 0)]
    [InlineData(0, -1)]
    [InlineData(0, 2)]
    public void RejectsPixelsOutsideTheImage(int x, int y)
    {
        var image = new RgbImage(3, 2);
        Assert.Throws<ArgumentOutOfRangeException>(() => image.GetPixel(x, y));
        Assert.Throws<ArgumentOutOfRangeException>(() => image.SetPixel(x, y, 1, 2, 3));
    }

    [Theory]
    [InlineData(0.0, 0)]
    [InlineData(1.0, 255)]
    [InlineData(-0.5, 0)]
    [InlineData(7.0, 255)]
    [InlineData(double.NaN, 0)]
    [InlineData(0.5, 128)]                // 127.5 rounds away from zero
    [InlineData(0.5 / 255, 1)]            // 0.5 rounds away from zero, not to even
    [InlineData(0.2, 51)]                 // linear: no gamma curve applied
    public void FromLinearClampsAndRounds(double value, byte expected)
    {
        var image = RgbImage.FromLinear(1, 1, (_, _) => (value, 0.0, 1.0));
        Assert.Equal((expected, (byte)0, (byte)255), image.GetPixel(0, 0));
    }

    [Fact]
    public void FromLinearPassesColumnAndRow()
    {
        var image = RgbImage.FromLinear(4, 3, (x, y) => (x / 255.0, y / 255.0, 0.0));
        Assert.Equal(((byte)3, (byte)2, (byte)0), image.GetPixel(3, 2));
    }
}
