using QuantumRayTracing.Output;
using QuantumRayTracing.Output.Plots;

namespace QuantumRayTracing.Tests.Output.Plots;

public class CanvasTests
{
    private static readonly PlotColour Red = new(200, 0, 0);

    [Fact]
    public void AHorizontalLineOnARowBoundaryFillsExactlyTwoRows()
    {
        var canvas = WhiteCanvas(30, 20);
        canvas.Line(5, 10, 25, 10, 2, Red);
        for (var y = 0; y < 20; y++)
        {
            var expected = y is 9 or 10 ? Red : PlotColour.White;
            Assert.Equal(expected, At(canvas, 15, y));
        }
    }

    [Fact]
    public void ASlantedLinePassesThroughItsEndPointsAndStaysInsideTheClip()
    {
        var canvas = WhiteCanvas(40, 40);
        canvas.Clip = new PixelRect(10, 10, 20, 20);
        canvas.Line(0.5, 0.5, 39.5, 30.5, 2, Red);
        // Halfway along, at (20, 15.5), the pixel on the line is solid.
        Assert.Equal(Red, At(canvas, 20, 15));
        for (var y = 0; y < 40; y++)
            for (var x = 0; x < 40; x++)
                if (!canvas.Clip.Contains(x, y)) Assert.Equal(PlotColour.White, At(canvas, x, y));
    }

    [Fact]
    public void LinesWithFarOffOrNonFiniteEndsDoNotThrow()
    {
        var canvas = WhiteCanvas(20, 20);
        canvas.Line(double.NaN, 0, 5, 5, 2, Red);
        canvas.Line(-1e300, 3, 1e300, 3, 2, Red);
        canvas.Line(-double.MaxValue, -double.MaxValue, double.MaxValue, double.MaxValue, 2, Red);
        canvas.Line(3, 3, 1e200, -1e250, 2, Red);
        Assert.Equal(Red, At(canvas, 10, 2));
    }

    [Theory]
    [MemberData(nameof(Shapes))]
    public void EveryMarkerIsSolidAtItsCentreAndStaysNearIt(MarkerShape shape)
    {
        foreach (var (cx, cy) in new[] { (20.5, 20.5), (20.0, 20.0), (20.9, 20.1) })
        {
            var canvas = WhiteCanvas(41, 41);
            canvas.Marker(shape, cx, cy, 4, Red);
            Assert.Equal(Red, At(canvas, (int)cx, (int)cy));
            for (var y = 0; y < 41; y++)
                for (var x = 0; x < 41; x++)
                    if (Math.Abs(x + 0.5 - cx) > 7 || Math.Abs(y + 0.5 - cy) > 7)
                        Assert.Equal(PlotColour.White, At(canvas, x, y));
        }
    }

    [Fact]
    public void MarkerShapesDiffer()
    {
        var drawn = Enum.GetValues<MarkerShape>().Select(shape =>
        {
            var canvas = WhiteCanvas(21, 21);
            canvas.Marker(shape, 10.5, 10.5, 4, Red);
            return Convert.ToHexString(canvas.Image.Pixels);
        }).ToList();
        Assert.Equal(drawn.Count, drawn.Distinct().Count());
    }

    public static TheoryData<MarkerShape> Shapes => new(Enum.GetValues<MarkerShape>());

    private static Canvas WhiteCanvas(int width, int height)
    {
        var canvas = new Canvas(new RgbImage(width, height));
        canvas.FillRect(0, 0, width, height, PlotColour.White);
        return canvas;
    }

    private static PlotColour At(Canvas canvas, int x, int y)
    {
        var (r, g, b) = canvas.Image.GetPixel(x, y);
        return new PlotColour(r, g, b);
    }
}
