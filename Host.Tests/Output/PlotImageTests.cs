using QuantumRayTracing.Output;

namespace QuantumRayTracing.Tests.Output;

public sealed class PlotImageTests
{
    private static PlotSpec Spec(params PlotSeries[] series) =>
        new("title", "x", "y", AxisScale.Log10, AxisScale.Log10, series, 400, 300);

    private static readonly PlotSeries Decades = new("decades", [(1, 1), (10, 100), (100, 10)]);

    [Fact]
    public void TheSameSpecGivesTheSameBytes() =>
        Assert.Equal(PngWriter.Encode(PlotImage.Render(Spec(Decades))), PngWriter.Encode(PlotImage.Render(Spec(Decades))));

    [Fact]
    public void EverySeriesIsDrawnInItsOwnColour()
    {
        var spec = Spec(Decades, new PlotSeries("other", [(2, 3), (30, 4)], Lines: false));
        using var plot = PlotImage.Build(spec);
        var image = PlotImage.Render(spec);
        var colours = Enumerable.Range(0, 2).Select(i => plot.Add.Palette.GetColor(i)).Select(c => (c.R, c.G, c.B)).ToArray();
        Assert.NotEqual(colours[0], colours[1]);
        foreach (var colour in colours)
            Assert.True(Count(image, colour) > 20, $"colour {colour} is drawn on {Count(image, colour)} pixels");
    }

    [Fact]
    public void PointsALogAxisCannotShowAreSkipped()
    {
        // Zero, negative and non-finite values on a log axis: the shown points are drawn, the rest dropped without error.
        var spec = Spec(new PlotSeries("mixed", [(1, 1), (0, 5), (2, -1), (double.NaN, 3), (10, 10), (100, double.PositiveInfinity)]));
        using var plot = PlotImage.Build(spec);
        var limits = plot.Axes.GetLimits();
        // Two points left, at log10 = 0 and 1 on both axes: the limits are that decade and a 3% margin.
        Assert.Equal((-0.03, 1.03, -0.03, 1.03), (Math.Round(limits.Left, 9), Math.Round(limits.Right, 9), Math.Round(limits.Bottom, 9), Math.Round(limits.Top, 9)));
        Assert.True(Count(PlotImage.Render(spec), (plot.Add.Palette.GetColor(0).R, plot.Add.Palette.GetColor(0).G, plot.Add.Palette.GetColor(0).B)) > 0);
    }

    [Theory]
    [InlineData(-0.2, 0.3, -1, 1)]
    [InlineData(0.5, 0.7, 0, 1)]
    [InlineData(2, 2, 2, 3)]
    [InlineData(-4.5, 3.2, -5, 4)]
    public void LogAxesSpanWholeDecades(double low, double high, double floor, double ceiling) =>
        Assert.Equal((floor, ceiling), PlotImage.DecadeLimits(low, high));

    [Theory]
    [InlineData(0, "1")]
    [InlineData(3, "1000")]
    [InlineData(-3, "0.001")]
    [InlineData(5, "1e5")]
    [InlineData(-4, "1e-4")]
    public void LogTicksAreLabelledWithTheirPowerOfTen(double exponent, string label) =>
        Assert.Equal(label, PlotImage.PowerOfTenLabel(exponent));

    private static int Count(RgbImage image, (byte R, byte G, byte B) colour)
    {
        var count = 0;
        for (var y = 0; y < image.Height; y++)
            for (var x = 0; x < image.Width; x++)
                if (image.GetPixel(x, y) == colour) count++;
        return count;
    }
}
