using System.Globalization;
using ScottPlot;
using ScottPlot.TickGenerators;

namespace QuantumRayTracing.Output;

/// <summary>
/// Draws a <see cref="PlotSpec"/> with ScottPlot into an <see cref="RgbImage"/>, which <see cref="ImageFiles"/>
/// writes like any other image: title, axis labels, a legend beside the data, and log axes where the spec asks.
/// A log axis is drawn the way ScottPlot 5 does it: the data goes in as log10 values, the major ticks sit on whole
/// powers of ten and are labelled with their values, and minor ticks mark 2x to 9x of each decade.
/// </summary>
public static class PlotImage
{
    /// <summary>The typeface of plots and montages; where it is not installed the system's default stands in.</summary>
    internal const string FontFamily = "DejaVu Sans";

    private const double Margin = 0.03;

    private static readonly MarkerShape[] Markers =
    [
        MarkerShape.FilledCircle, MarkerShape.FilledSquare, MarkerShape.FilledDiamond, MarkerShape.FilledTriangleUp,
        MarkerShape.FilledTriangleDown, MarkerShape.Cross, MarkerShape.Eks,
    ];

    /// <summary>
    /// Draws <paramref name="spec"/>. Points with a non-finite coordinate, or a coordinate that is not positive on a log
    /// axis, are skipped, and a line breaks there rather than bridging the gap.
    /// </summary>
    public static RgbImage Render(PlotSpec spec)
    {
        ArgumentNullException.ThrowIfNull(spec);
        using var plot = Build(spec);
        return Render(plot, spec.Width, spec.Height);
    }

    /// <summary>Draws a ScottPlot plot built elsewhere (a chart a <see cref="PlotSpec"/> cannot describe, such as bars).</summary>
    internal static RgbImage Render(Plot plot, int width, int height)
    {
        var (surface, info) = SkiaPixels.Surface(width, height);
        using var _ = surface;
        plot.Render(surface.Canvas, width, height);
        return SkiaPixels.ToImage(surface, info);
    }

    /// <summary>The ScottPlot plot of <paramref name="spec"/>, before rendering (the caller disposes it).</summary>
    internal static Plot Build(PlotSpec spec)
    {
        var plot = new Plot();
        plot.FigureBackground.Color = Colors.White;
        plot.Font.Set(FontFamily);
        plot.Title(spec.Title);
        plot.XLabel(spec.XLabel);
        plot.YLabel(spec.YLabel);
        for (var i = 0; i < spec.Series.Count; i++) AddSeries(plot, spec, i);
        if (spec.XScale == AxisScale.Log10) plot.Axes.Bottom.TickGenerator = LogTicks();
        if (spec.YScale == AxisScale.Log10) plot.Axes.Left.TickGenerator = LogTicks();
        plot.Axes.AutoScale();
        // Whole decades on a log axis, so at least two labelled powers of ten frame the data, and a margin of 3% so
        // points on a power of ten are not cut by the frame.
        var data = plot.Axes.GetDataLimits();
        if (spec.XScale == AxisScale.Log10 && DecadeLimits(data.Left, data.Right) is { } x)
            plot.Axes.SetLimitsX(x.Low - Margin * (x.High - x.Low), x.High + Margin * (x.High - x.Low));
        if (spec.YScale == AxisScale.Log10 && DecadeLimits(data.Bottom, data.Top) is { } y)
            plot.Axes.SetLimitsY(y.Low - Margin * (y.High - y.Low), y.High + Margin * (y.High - y.Low));
        plot.Grid.MajorLineColor = Colors.Black.WithOpacity(0.15);
        plot.Grid.MinorLineColor = Colors.Black.WithOpacity(0.05);
        plot.Grid.MinorLineWidth = 1;
        if (spec.Series.Any(s => s.Points.Any(p => Showable(spec, p))))
            plot.ShowLegend(Edge.Right);
        return plot;
    }

    // One scatter per unbroken run of showable points; the first carries the legend entry.
    private static void AddSeries(Plot plot, PlotSpec spec, int index)
    {
        var series = spec.Series[index];
        var colour = plot.Add.Palette.GetColor(index);
        var labelled = false;
        foreach (var run in Runs(spec, series.Points))
        {
            var scatter = plot.Add.Scatter(run.Select(p => p.X).ToArray(), run.Select(p => p.Y).ToArray(), colour);
            scatter.LineWidth = series.Lines ? 2 : 0;
            scatter.MarkerSize = series.Markers ? 8 : 0;
            scatter.MarkerShape = Markers[index % Markers.Length];
            if (!labelled) scatter.LegendText = series.Label;
            labelled = true;
        }
    }

    // The points in axis units (log10 on a log axis), split where a point cannot be shown.
    private static List<List<(double X, double Y)>> Runs(PlotSpec spec, IReadOnlyList<(double X, double Y)> points)
    {
        var runs = new List<List<(double X, double Y)>> { new() };
        foreach (var point in points)
        {
            if (!Showable(spec, point))
            {
                if (runs[^1].Count > 0) runs.Add([]);
                continue;
            }
            runs[^1].Add((ToAxis(point.X, spec.XScale), ToAxis(point.Y, spec.YScale)));
        }
        return runs.Where(r => r.Count > 0).ToList();
    }

    private static bool Showable(PlotSpec spec, (double X, double Y) point) =>
        Showable(point.X, spec.XScale) && Showable(point.Y, spec.YScale);

    private static bool Showable(double value, AxisScale scale) => double.IsFinite(value) && (scale == AxisScale.Linear || value > 0);

    private static double ToAxis(double value, AxisScale scale) => scale == AxisScale.Log10 ? Math.Log10(value) : value;

    private static NumericAutomatic LogTicks() => new()
    {
        MinorTickGenerator = new LogMinorTickGenerator(),
        IntegerTicksOnly = true,
        LabelFormatter = PowerOfTenLabel,
    };

    /// <summary>The whole decades around log10 values <paramref name="low"/>..<paramref name="high"/>, or null without data.</summary>
    internal static (double Low, double High)? DecadeLimits(double low, double high)
    {
        if (!double.IsFinite(low) || !double.IsFinite(high)) return null;
        var (floor, ceiling) = (Math.Floor(low), Math.Ceiling(high));
        return (floor, ceiling > floor ? ceiling : floor + 1);
    }

    /// <summary>The label of the tick at log10 value <paramref name="exponent"/>: 0.001 to 10000 written out, 1e-5 style beyond.</summary>
    internal static string PowerOfTenLabel(double exponent)
    {
        var power = (int)Math.Round(exponent);
        return power is >= -3 and <= 4
            ? Math.Pow(10, power).ToString("0.###", CultureInfo.InvariantCulture)
            : $"1e{power}";
    }
}
