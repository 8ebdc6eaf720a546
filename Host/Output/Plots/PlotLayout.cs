namespace QuantumRayTracing.Output.Plots;

/// <summary>
/// Where everything of a plot goes: the plot area, the two axes with their ranges and ticks, the text rows and
/// the legend. <see cref="LinePlot.Render"/> draws exactly this layout, so <see cref="Map"/> tells where a data
/// point lands in the image.
/// </summary>
public sealed class PlotLayout
{
    /// <summary>The smallest width <see cref="LinePlot.Render"/> accepts, in pixels.</summary>
    public const int MinWidth = 200;

    /// <summary>The smallest height <see cref="LinePlot.Render"/> accepts, in pixels.</summary>
    public const int MinHeight = 150;

    /// <summary>The largest width or height accepted, which keeps a mistyped size from allocating gigabytes.</summary>
    public const int MaxSide = 8192;

    private PlotLayout(PixelRect plotArea, PlotAxis x, PlotAxis y)
    {
        PlotArea = plotArea;
        X = x;
        Y = y;
    }

    /// <summary>
    /// The pixels inside the axes frame, where data is drawn (and clipped). The frame itself runs along the
    /// column left of it, the column at <see cref="PixelRect.Right"/>, the row above it and the row at
    /// <see cref="PixelRect.Bottom"/>.
    /// </summary>
    public PixelRect PlotArea { get; }

    /// <summary>The horizontal axis, from <see cref="PixelRect.Left"/> to <see cref="PixelRect.Right"/> of the plot area.</summary>
    public PlotAxis X { get; }

    /// <summary>The vertical axis, from <see cref="PixelRect.Bottom"/> (its minimum) up to <see cref="PixelRect.Top"/>.</summary>
    public PlotAxis Y { get; }

    /// <summary>The legend box, or null when the plot has no series.</summary>
    public PixelRect? Legend { get; private init; }

    /// <summary>Whether at least one point can be shown; without any the plot says "no data".</summary>
    public bool HasData { get; private init; }

    /// <summary>
    /// The continuous pixel coordinates of data point (<paramref name="x"/>, <paramref name="y"/>); the pixel
    /// there is (floor(X), floor(Y)). NaN for a coordinate its axis cannot show.
    /// </summary>
    public (double X, double Y) Map(double x, double y) => (X.ToPixel(x), Y.ToPixel(y));

    // Drawing parameters, all scaled with the text so bigger images stay in proportion.
    internal int TextScale { get; private init; }
    internal int TitleScale => TextScale + 1;
    internal int Padding => 10 * TextScale;
    internal int TickLength => 5 * TextScale;
    internal int MinorTickLength => 3 * TextScale;
    internal int TickLabelGap => 3 * TextScale;
    internal double LineWidth => 2 * TextScale;
    internal double MarkerRadius => 4 * TextScale;

    // Tops of the text rows; the y label sits above the axis, so no text needs turning.
    internal int TitleTop { get; private init; }
    internal int YLabelTop { get; private init; }
    internal int XTickLabelTop { get; private init; }
    internal int XLabelTop { get; private init; }

    /// <summary>Legend rows: a series index and its (possibly shortened) label, or index -1 for a "+n more" row.</summary>
    internal IReadOnlyList<(int Series, string Text)> LegendRows { get; private init; } = [];
    internal int LegendRowHeight => 14 * TextScale;
    internal int LegendSwatchWidth => 24 * TextScale;
    internal int LegendInset => 6 * TextScale;

    /// <summary>The layout of <paramref name="spec"/>.</summary>
    /// <exception cref="ArgumentException">The size is outside the accepted range, or the series list, a series or its points are null.</exception>
    internal static PlotLayout Compute(PlotSpec spec)
    {
        Validate(spec);
        int width = spec.Width, height = spec.Height;
        // Text grows by whole font pixels: 1x up to about 1600x1000, then 2x, and so on.
        var s = Math.Clamp(Math.Min(width / 800, height / 500), 1, 8);
        var (xs, ys) = ShownCoordinates(spec);
        var pad = 10 * s;
        var textHeight = BitmapFont.GlyphHeight * s;
        var capHeight = BitmapFont.CapHeight * s;

        // Rows from the top: title, y label, then room for half of the top y tick label.
        var top = pad;
        var titleTop = top;
        if (!string.IsNullOrEmpty(spec.Title)) top += BitmapFont.GlyphHeight * (s + 1) + 6 * s;
        var yLabelTop = top;
        if (!string.IsNullOrEmpty(spec.YLabel)) top += textHeight + 4 * s;
        var plotTop = top + capHeight / 2 + 2 * s;

        // Rows from the bottom: x label, x tick labels, tick marks, then the frame row.
        var bottom = height - pad;
        var xLabelTop = bottom - textHeight;
        if (!string.IsNullOrEmpty(spec.XLabel)) bottom = xLabelTop - 5 * s;
        var xTickLabelTop = bottom - textHeight;
        var plotBottom = xTickLabelTop - 3 * s - 5 * s - 1;
        var plotHeight = Math.Max(1, plotBottom - plotTop);

        var y = new PlotAxis(spec.YScale, PlotAxis.RangeOf(ys, spec.YScale), plotTop + plotHeight, plotTop);
        var yGap = 6 * s;
        y.Ticks = AxisTicks.For(y, 45 * s, ticks => LabelsApart(ticks, y, _ => capHeight, yGap));
        var yLabelWidth = y.Ticks.Where(t => t.Label is not null).Select(t => BitmapFont.Measure(t.Label!, s).Width).DefaultIfEmpty(0).Max();
        var plotLeft = pad + yLabelWidth + 3 * s + 5 * s + 1;

        // The legend takes a column on the right, at most 30% of the width; labels are shortened to fit it.
        PixelRect? legend = null;
        List<(int, string)> rows = [];
        var plotRight = width - pad - 12 * s;
        if (spec.Series.Count > 0)
        {
            int inset = 6 * s, swatch = 24 * s, rowHeight = 14 * s;
            var textRoom = (int)(width * 0.3) - 3 * inset - swatch;
            var rowsFit = Math.Max(1, (plotHeight - 2 * inset) / rowHeight);
            var shown = spec.Series.Count <= rowsFit ? spec.Series.Count : rowsFit - 1;
            for (var i = 0; i < shown; i++) rows.Add((i, Shorten(spec.Series[i].Label ?? "", textRoom, s)));
            if (shown < spec.Series.Count) rows.Add((-1, Shorten($"+{spec.Series.Count - shown} more", textRoom, s)));
            var textWidth = rows.Max(r => BitmapFont.Measure(r.Item2, s).Width);
            var legendWidth = 3 * inset + swatch + textWidth;
            var legendHeight = 2 * inset + rows.Count * rowHeight;
            legend = new PixelRect(width - pad - legendWidth, plotTop, legendWidth, legendHeight);
            plotRight = legend.Value.Left - 12 * s;
        }
        var plotWidth = Math.Max(1, plotRight - plotLeft);

        var x = new PlotAxis(spec.XScale, PlotAxis.RangeOf(xs, spec.XScale), plotLeft, plotLeft + plotWidth);
        var xGap = 10 * s;
        x.Ticks = AxisTicks.For(x, 80 * s, ticks => LabelsApart(ticks, x, label => BitmapFont.Measure(label, s).Width, xGap));

        return new PlotLayout(new PixelRect(plotLeft, plotTop, plotWidth, plotHeight), x, y)
        {
            Legend = legend,
            HasData = xs.Count > 0,
            TextScale = s,
            TitleTop = titleTop,
            YLabelTop = yLabelTop,
            XTickLabelTop = xTickLabelTop,
            XLabelTop = xLabelTop,
            LegendRows = rows,
        };
    }

    /// <summary>Whether a point can be shown: both coordinates finite, and positive on a log axis.</summary>
    internal static bool TryMapToAxisUnits(PlotSpec spec, (double X, double Y) point, out (double X, double Y) at)
    {
        var shown = PlotAxis.TryToAxisUnits(spec.XScale, point.X, out var x) & PlotAxis.TryToAxisUnits(spec.YScale, point.Y, out var y);
        at = (x, y);
        return shown;
    }

    private static void Validate(PlotSpec spec)
    {
        ArgumentNullException.ThrowIfNull(spec);
        if (spec.Width < MinWidth || spec.Height < MinHeight || spec.Width > MaxSide || spec.Height > MaxSide)
            throw new ArgumentException(
                $"A plot must be {MinWidth}x{MinHeight} to {MaxSide}x{MaxSide} pixels; this one is {spec.Width}x{spec.Height}.", nameof(spec));
        if (spec.Series is null) throw new ArgumentException("The plot's series list is null.", nameof(spec));
        for (var i = 0; i < spec.Series.Count; i++)
            if (spec.Series[i]?.Points is null)
                throw new ArgumentException($"Series {i} of the plot, or its list of points, is null.", nameof(spec));
    }

    // The axis-unit coordinates of every point that can be shown, for the data ranges.
    private static (List<double> Xs, List<double> Ys) ShownCoordinates(PlotSpec spec)
    {
        List<double> xs = [], ys = [];
        foreach (var series in spec.Series)
            foreach (var point in series.Points)
                if (TryMapToAxisUnits(spec, point, out var at))
                {
                    xs.Add(at.X);
                    ys.Add(at.Y);
                }
        return (xs, ys);
    }

    // Whether neighbouring labels along the axis keep at least `gap` pixels between their extents.
    private static bool LabelsApart(IReadOnlyList<Tick> ticks, PlotAxis axis, Func<string, int> extent, int gap)
    {
        var labelled = ticks.Where(t => t.Label is not null)
            .Select(t => (Pixel: axis.PixelOf(t.At), Extent: extent(t.Label!)))
            .OrderBy(t => t.Pixel).ToList();
        for (var i = 1; i < labelled.Count; i++)
            if (labelled[i].Pixel - labelled[i - 1].Pixel < (labelled[i].Extent + labelled[i - 1].Extent) / 2.0 + gap)
                return false;
        return true;
    }

    // The label cut short with "..." so it is at most `room` pixels wide.
    private static string Shorten(string label, int room, int scale)
    {
        if (BitmapFont.Measure(label, scale).Width <= room) return label;
        var chars = Math.Max(0, (room / scale + 1) / BitmapFont.Advance - 3);
        return label[..Math.Min(chars, label.Length)] + "...";
    }
}
