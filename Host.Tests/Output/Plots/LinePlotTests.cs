using QuantumRayTracing.Output;
using QuantumRayTracing.Output.Plots;

namespace QuantumRayTracing.Tests.Output.Plots;

public class LinePlotTests
{
    private static readonly (double X, double Y)[] Zigzag = [(1, 2), (2, 5), (3, 3), (4, 8)];

    [Fact]
    public void ADataPointLandsWhereTheLinearMappingOfThePlotAreaPutsIt()
    {
        var spec = Spec(AxisScale.Linear, AxisScale.Linear, new PlotSeries("zigzag", Zigzag));
        var layout = LinePlot.Layout(spec);
        var image = LinePlot.Render(spec);
        var area = layout.PlotArea;

        // The ranges cover the data with a small margin.
        Assert.InRange(layout.X.Min, 0.5, 1 - 1e-9);
        Assert.InRange(layout.X.Max, 4 + 1e-9, 4.5);
        Assert.InRange(layout.Y.Min, 1, 2 - 1e-9);
        Assert.InRange(layout.Y.Max, 8 + 1e-9, 9);

        foreach (var (x, y) in Zigzag)
        {
            // Computed here from the plot area alone: x grows rightwards, y upwards from the bottom edge.
            var px = area.Left + (x - layout.X.Min) / (layout.X.Max - layout.X.Min) * area.Width;
            var py = area.Bottom - (y - layout.Y.Min) / (layout.Y.Max - layout.Y.Min) * area.Height;
            var mapped = layout.Map(x, y);
            Assert.Equal(px, mapped.X, 1e-9);
            Assert.Equal(py, mapped.Y, 1e-9);
            Assert.Equal(PlotPalette.ColourFor(0), At(image, (int)px, (int)py));
        }
        // Far from the line, the top-left of the data area is background.
        var (emptyX, emptyY) = layout.Map(1.2, 7.5);
        Assert.NotEqual(PlotPalette.ColourFor(0), At(image, (int)emptyX, (int)emptyY));
    }

    [Fact]
    public void PowersOfTenAreEquallySpacedOnALogAxis()
    {
        (double, double)[] points = [(1, 5), (10, 5), (100, 5)];
        var log = MarkerCentres(Spec(AxisScale.Log10, AxisScale.Linear, new PlotSeries("p", points, Lines: false)), 5);
        Assert.Equal(3, log.Count);
        Assert.True(log[1] - log[0] > 100, "markers should be well apart");
        Assert.Equal(log[1] - log[0], log[2] - log[1], 1.0);

        // The same points on a linear axis are not: 1 and 10 crowd together at the left.
        var linear = MarkerCentres(Spec(AxisScale.Linear, AxisScale.Linear, new PlotSeries("p", points, Lines: false)), 5);
        Assert.Equal(3, linear.Count);
        Assert.True(linear[2] - linear[1] > 5 * (linear[1] - linear[0]));

        var layout = LinePlot.Layout(Spec(AxisScale.Log10, AxisScale.Log10, new PlotSeries("p", [(1, 1e-6), (10, 1e-3), (100, 1)])));
        Assert.Equal(layout.Map(10, 1).X - layout.Map(1, 1).X, layout.Map(100, 1).X - layout.Map(10, 1).X, 1e-9);
        Assert.Equal(layout.Map(1, 1e-3).Y - layout.Map(1, 1e-6).Y, layout.Map(1, 1).Y - layout.Map(1, 1e-3).Y, 1e-9);
    }

    [Fact]
    public void PointsThatCannotBeShownAreSkippedWithoutError()
    {
        (double, double)[] points =
        [
            (1, 1), (double.NaN, 2), (2, double.PositiveInfinity), (-1, 3), (3, 0), (double.NegativeInfinity, 4),
            (4, 100), (5, -7), (0, 50),
        ];
        var spec = Spec(AxisScale.Log10, AxisScale.Log10, new PlotSeries("mixed", points));
        var layout = LinePlot.Layout(spec);
        var image = LinePlot.Render(spec);

        // Only (1, 1) and (4, 100) count towards the ranges.
        Assert.True(layout.HasData);
        Assert.InRange(layout.X.Min, 0.8, 1 - 1e-9);
        Assert.InRange(layout.X.Max, 4 + 1e-9, 5);
        Assert.InRange(layout.Y.Min, 0.5, 1 - 1e-9);
        Assert.InRange(layout.Y.Max, 100 + 1e-9, 200);
        Assert.True(double.IsNaN(layout.Map(-1, 3).X));
        Assert.True(double.IsNaN(layout.Map(3, 0).Y));

        foreach (var (x, y) in new[] { (1.0, 1.0), (4.0, 100.0) })
        {
            var (px, py) = layout.Map(x, y);
            Assert.Equal(PlotPalette.ColourFor(0), At(image, (int)px, (int)py));
        }

        // The same points on linear axes keep the negative values and the zero.
        var linear = LinePlot.Layout(Spec(AxisScale.Linear, AxisScale.Linear, new PlotSeries("mixed", points)));
        Assert.True(linear.X.Min < -1 && linear.Y.Min < -7);
    }

    public static TheoryData<string, PlotSeries[]> Empty => new()
    {
        { "no series", [] },
        { "series without points", [new PlotSeries("empty", [])] },
        { "only unusable points", [new PlotSeries("bad", [(double.NaN, 1), (2, -3), (0, 1), (double.PositiveInfinity, double.NaN)])] },
    };

    [Theory]
    [MemberData(nameof(Empty))]
    public void WithNothingToShowTheAxesAreStillDrawnWithANote(string name, PlotSeries[] series)
    {
        var spec = Spec(AxisScale.Log10, AxisScale.Log10, series);
        var layout = LinePlot.Layout(spec);
        var image = LinePlot.Render(spec);
        Assert.False(layout.HasData, name);
        Assert.Equal((spec.Width, spec.Height), (image.Width, image.Height));

        var area = layout.PlotArea;
        Assert.Equal(PlotColour.Black, At(image, area.Left - 1, area.Top + area.Height / 2));
        Assert.Equal(PlotColour.Black, At(image, area.Left + area.Width / 2, area.Bottom));
        // "no data" in grey, in the middle of the plot area.
        var grey = 0;
        for (var y = area.Top; y < area.Bottom; y++)
            for (var x = area.Left; x < area.Right; x++)
                if (At(image, x, y) == new PlotColour(120, 120, 120)) grey++;
        Assert.True(grey > 30, $"{grey} note pixels");
    }

    [Fact]
    public void TheSameSpecGivesTheSameBytes()
    {
        static PlotSpec Make() => Spec(AxisScale.Linear, AxisScale.Log10,
            new PlotSeries("a", Enumerable.Range(1, 50).Select(i => (i * 0.37, Math.Exp(Math.Sin(i)))).ToList()),
            new PlotSeries("b", Enumerable.Range(1, 50).Select(i => (i * 0.5, i * 1.1)).ToList(), Markers: false));
        var first = PngWriter.Encode(LinePlot.Render(Make()));
        var second = PngWriter.Encode(LinePlot.Render(Make()));
        Assert.Equal(first, second);

        var moved = Make() with { Title = "other" };
        Assert.NotEqual(first, PngWriter.Encode(LinePlot.Render(moved)));
    }

    [Fact]
    public void TheLegendShowsEverySeriesColourOutsideTheData()
    {
        var series = Enumerable.Range(0, 3)
            .Select(i => new PlotSeries($"series {i}", [(0, i), (1, i + 1)], Lines: i != 1, Markers: i != 2))
            .ToArray();
        var spec = Spec(AxisScale.Linear, AxisScale.Linear, series);
        var layout = LinePlot.Layout(spec);
        var image = LinePlot.Render(spec);
        var legend = Assert.IsType<PixelRect>(layout.Legend);
        Assert.True(legend.Left > layout.PlotArea.Right, "the legend sits right of the plot area");

        for (var i = 0; i < series.Length; i++)
        {
            var swatch = 0;
            for (var y = legend.Top; y < legend.Bottom; y++)
                for (var x = legend.Left; x < legend.Right; x++)
                    if (At(image, x, y) == PlotPalette.ColourFor(i)) swatch++;
            Assert.True(swatch >= 20, $"series {i} has {swatch} legend pixels");
        }
        // Labels are drawn in black inside the box.
        var text = 0;
        for (var y = legend.Top + 1; y < legend.Bottom - 1; y++)
            for (var x = legend.Left + 1; x < legend.Right - 1; x++)
                if (At(image, x, y) == PlotColour.Black) text++;
        Assert.True(text > 50);
    }

    [Fact]
    public void TitleAndTickLabelsAreDrawnAroundThePlotArea()
    {
        var spec = Spec(AxisScale.Linear, AxisScale.Linear, new PlotSeries("zigzag", Zigzag));
        var area = LinePlot.Layout(spec).PlotArea;
        var image = LinePlot.Render(spec);
        Assert.True(CountBlack(image, new PixelRect(0, 0, image.Width, area.Top - 12)) > 100, "title");
        Assert.True(CountBlack(image, new PixelRect(0, area.Top, area.Left - 7, area.Height)) > 50, "y tick labels");
        Assert.True(CountBlack(image, new PixelRect(area.Left, area.Bottom + 7, area.Width, image.Height - area.Bottom - 7)) > 50, "x tick labels");

        var untitled = LinePlot.Render(spec with { Title = "", YLabel = "" });
        Assert.Equal(0, CountBlack(untitled, new PixelRect(0, 0, untitled.Width, 10)));
    }

    [Theory]
    [InlineData(199, 500)]
    [InlineData(800, 149)]
    [InlineData(0, 0)]
    [InlineData(-400, 300)]
    [InlineData(8193, 500)]
    public void RejectsSizesOutsideTheAcceptedRange(int width, int height)
    {
        var spec = Spec(AxisScale.Linear, AxisScale.Linear, new PlotSeries("a", Zigzag)) with { Width = width, Height = height };
        var error = Assert.Throws<ArgumentException>(() => LinePlot.Render(spec));
        Assert.Contains("200x150", error.Message);
    }

    [Fact]
    public void TheSmallestSizeStillRenders()
    {
        var spec = Spec(AxisScale.Log10, AxisScale.Linear, new PlotSeries("a long label for a small plot", Zigzag)) with { Width = 200, Height = 150 };
        var image = LinePlot.Render(spec);
        Assert.Equal((200, 150), (image.Width, image.Height));
    }

    [Fact]
    public void RejectsMissingSeriesOrPoints()
    {
        var spec = Spec(AxisScale.Linear, AxisScale.Linear);
        Assert.Throws<ArgumentException>(() => LinePlot.Render(spec with { Series = null! }));
        Assert.Throws<ArgumentException>(() => LinePlot.Render(spec with { Series = [null!] }));
        Assert.Throws<ArgumentException>(() => LinePlot.Render(spec with { Series = [new PlotSeries("a", null!)] }));
    }

    [Fact]
    public void ThePaletteHasEightDistinctColoursThatStandOutFromTheBackground()
    {
        var colours = PlotPalette.Colours;
        Assert.True(colours.Count >= 8);
        Assert.Equal(colours.Count, colours.Distinct().Count());
        // Saturated: the channels spread by at least 60, unlike white, black and the greys of grid and text.
        Assert.All(colours, c => Assert.True(new[] { c.R, c.G, c.B }.Max() - new[] { c.R, c.G, c.B }.Min() >= 60, c.ToString()));
        Assert.Equal(PlotPalette.ColourFor(0), PlotPalette.ColourFor(colours.Count));
        Assert.NotEqual(PlotPalette.MarkerFor(0), PlotPalette.MarkerFor(1));
    }

    private static PlotSpec Spec(AxisScale x, AxisScale y, params PlotSeries[] series) =>
        new("Test plot", "x value", "y value", x, y, series);

    // Columns of the centres of runs of the first series' colour along the row where y lands.
    private static List<double> MarkerCentres(PlotSpec spec, double y)
    {
        var image = LinePlot.Render(spec);
        var row = (int)Math.Floor(LinePlot.Layout(spec).Map(1, y).Y);
        var centres = new List<double>();
        int? start = null;
        for (var x = 0; x <= image.Width; x++)
        {
            var inRun = x < image.Width && At(image, x, row) == PlotPalette.ColourFor(0);
            if (inRun && start is null) start = x;
            if (!inRun && start is { } s)
            {
                centres.Add((s + x) / 2.0);
                start = null;
            }
        }
        return centres;
    }

    private static int CountBlack(RgbImage image, PixelRect area)
    {
        var count = 0;
        for (var y = area.Top; y < area.Bottom; y++)
            for (var x = area.Left; x < area.Right; x++)
                if (At(image, x, y) == PlotColour.Black) count++;
        return count;
    }

    private static PlotColour At(RgbImage image, int x, int y)
    {
        var (r, g, b) = image.GetPixel(x, y);
        return new PlotColour(r, g, b);
    }
}
