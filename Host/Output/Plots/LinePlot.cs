namespace QuantumRayTracing.Output.Plots;

/// <summary>
/// Renders line and scatter plots to an <see cref="RgbImage"/> without any drawing library: white background,
/// light grey grid, black framed axes with ticks and numeric labels, title, axis labels and a legend. The
/// same spec always gives the same pixels.
/// </summary>
public static class LinePlot
{
    private static readonly PlotColour Text = PlotColour.Black;
    private static readonly PlotColour Frame = PlotColour.Black;
    private static readonly PlotColour MajorGrid = new(222, 222, 222);
    private static readonly PlotColour MinorGrid = new(242, 242, 242);
    private static readonly PlotColour LegendBorder = new(150, 150, 150);
    private static readonly PlotColour Note = new(120, 120, 120);

    /// <summary>
    /// Draws <paramref name="spec"/>. Points with a non-finite coordinate, or a coordinate that is not positive on a
    /// log axis, are skipped (a line breaks there); with nothing left to show the axes are still drawn, with a
    /// "no data" note.
    /// </summary>
    /// <exception cref="ArgumentException">The size is below <see cref="PlotLayout.MinWidth"/> x
    /// <see cref="PlotLayout.MinHeight"/> or above <see cref="PlotLayout.MaxSide"/>, or the series list, a series or
    /// its points are null.</exception>
    public static RgbImage Render(PlotSpec spec)
    {
        var layout = PlotLayout.Compute(spec);
        var canvas = new Canvas(new RgbImage(spec.Width, spec.Height));
        canvas.FillRect(0, 0, spec.Width, spec.Height, PlotColour.White);
        DrawGrid(canvas, layout);
        DrawSeries(canvas, layout, spec);
        DrawAxes(canvas, layout);
        DrawLabels(canvas, layout, spec);
        DrawLegend(canvas, layout, spec);
        return canvas.Image;
    }

    /// <summary>
    /// The layout <see cref="Render"/> uses for <paramref name="spec"/>: plot area, axis ranges and legend box,
    /// for placing annotations or checking where data lands.
    /// </summary>
    /// <exception cref="ArgumentException">As for <see cref="Render"/>.</exception>
    public static PlotLayout Layout(PlotSpec spec) => PlotLayout.Compute(spec);

    private static void DrawGrid(Canvas canvas, PlotLayout layout)
    {
        var area = layout.PlotArea;
        canvas.Clip = area;
        // Minor lines first, so majors stay unbroken where the two meet.
        foreach (var major in new[] { false, true })
        {
            var colour = major ? MajorGrid : MinorGrid;
            foreach (var tick in layout.X.Ticks.Where(t => t.Major == major))
                if (Pixel(layout.X.PixelOf(tick.At)) is { } column)
                    canvas.VerticalRule(column, area.Top, area.Bottom - 1, colour);
            foreach (var tick in layout.Y.Ticks.Where(t => t.Major == major))
                if (Pixel(layout.Y.PixelOf(tick.At)) is { } row)
                    canvas.HorizontalRule(area.Left, area.Right - 1, row, colour);
        }
        canvas.Clip = new PixelRect(0, 0, canvas.Image.Width, canvas.Image.Height);
    }

    private static void DrawSeries(Canvas canvas, PlotLayout layout, PlotSpec spec)
    {
        canvas.Clip = layout.PlotArea;
        for (var i = 0; i < spec.Series.Count; i++)
        {
            var series = spec.Series[i];
            var colour = PlotPalette.ColourFor(i);
            var points = series.Points
                .Select(p => PlotLayout.TryMapToAxisUnits(spec, p, out var at)
                    ? (layout.X.PixelOf(at.X), layout.Y.PixelOf(at.Y))
                    : ((double X, double Y)?)null)
                .ToList();
            if (series.Lines)
                for (var j = 1; j < points.Count; j++)
                    if (points[j - 1] is { } from && points[j] is { } to)
                        canvas.Line(from.X, from.Y, to.X, to.Y, layout.LineWidth, colour);
            if (series.Markers)
                foreach (var point in points)
                    if (point is { } p)
                        canvas.Marker(PlotPalette.MarkerFor(i), p.X, p.Y, layout.MarkerRadius, colour);
        }
        canvas.Clip = new PixelRect(0, 0, canvas.Image.Width, canvas.Image.Height);
    }

    private static void DrawAxes(Canvas canvas, PlotLayout layout)
    {
        var area = layout.PlotArea;
        canvas.StrokeRect(new PixelRect(area.Left - 1, area.Top - 1, area.Width + 2, area.Height + 2), Frame);
        var s = layout.TextScale;
        foreach (var tick in layout.X.Ticks)
        {
            if (Pixel(layout.X.PixelOf(tick.At)) is not { } column || column < area.Left - 1 || column > area.Right) continue;
            var length = tick.Major ? layout.TickLength : layout.MinorTickLength;
            canvas.VerticalRule(column, area.Bottom + 1, area.Bottom + length, Frame);
            if (tick.Label is null) continue;
            var width = BitmapFont.Measure(tick.Label, s).Width;
            BitmapFont.DrawText(canvas.Image, tick.Label, column - width / 2, layout.XTickLabelTop, Text, s);
        }
        foreach (var tick in layout.Y.Ticks)
        {
            if (Pixel(layout.Y.PixelOf(tick.At)) is not { } row || row < area.Top - 1 || row > area.Bottom) continue;
            var length = tick.Major ? layout.TickLength : layout.MinorTickLength;
            canvas.HorizontalRule(area.Left - 1 - length, area.Left - 2, row, Frame);
            if (tick.Label is null) continue;
            var width = BitmapFont.Measure(tick.Label, s).Width;
            var right = area.Left - 1 - layout.TickLength - layout.TickLabelGap;
            // Centred on the capitals and digits, which is what a number shows.
            BitmapFont.DrawText(canvas.Image, tick.Label, right - width, row - BitmapFont.CapHeight * s / 2, Text, s);
        }
    }

    private static void DrawLabels(Canvas canvas, PlotLayout layout, PlotSpec spec)
    {
        var area = layout.PlotArea;
        var s = layout.TextScale;
        var image = canvas.Image;
        if (!string.IsNullOrEmpty(spec.Title))
            DrawCentred(image, spec.Title, area.Left + area.Width / 2, layout.TitleTop, layout.TitleScale, layout.Padding);
        if (!string.IsNullOrEmpty(spec.YLabel))
            BitmapFont.DrawText(image, spec.YLabel, layout.Padding, layout.YLabelTop, Text, s);
        if (!string.IsNullOrEmpty(spec.XLabel))
            DrawCentred(image, spec.XLabel, area.Left + area.Width / 2, layout.XLabelTop, s, layout.Padding);
        if (!layout.HasData)
        {
            const string note = "no data";
            var (width, _) = BitmapFont.Measure(note, s);
            BitmapFont.DrawText(image, note, area.Left + (area.Width - width) / 2,
                area.Top + (area.Height - BitmapFont.CapHeight * s) / 2, Note, s);
        }
    }

    // Centred on `centre`, but moved inward to stay within the padding when it would run off the image.
    private static void DrawCentred(RgbImage image, string text, int centre, int top, int scale, int padding)
    {
        var width = BitmapFont.Measure(text, scale).Width;
        var left = Math.Max(padding, Math.Min(centre - width / 2, image.Width - padding - width));
        BitmapFont.DrawText(image, text, left, top, Text, scale);
    }

    private static void DrawLegend(Canvas canvas, PlotLayout layout, PlotSpec spec)
    {
        if (layout.Legend is not { } box) return;
        var s = layout.TextScale;
        canvas.FillRect(box.Left, box.Top, box.Width, box.Height, PlotColour.White);
        canvas.StrokeRect(box, LegendBorder);
        var inset = layout.LegendInset;
        for (var row = 0; row < layout.LegendRows.Count; row++)
        {
            var (index, text) = layout.LegendRows[row];
            var top = box.Top + inset + row * layout.LegendRowHeight;
            // An integer centre puts a two-pixel line exactly on two rows, so it stays crisp.
            var centre = top + layout.LegendRowHeight / 2;
            var swatchLeft = box.Left + inset;
            if (index >= 0)
            {
                var series = spec.Series[index];
                var colour = PlotPalette.ColourFor(index);
                // A series drawn with neither lines nor markers still gets a line, so its colour shows.
                if (series.Lines || !series.Markers)
                    canvas.Line(swatchLeft, centre, swatchLeft + layout.LegendSwatchWidth, centre, layout.LineWidth, colour);
                if (series.Markers)
                    canvas.Marker(PlotPalette.MarkerFor(index), swatchLeft + layout.LegendSwatchWidth / 2.0, centre, layout.MarkerRadius, colour);
            }
            BitmapFont.DrawText(canvas.Image, text, swatchLeft + layout.LegendSwatchWidth + inset,
                centre - (BitmapFont.CapHeight * s + 1) / 2, index >= 0 ? Text : Note, s);
        }
    }

    // The pixel holding a coordinate, or null when it is not finite (or absurdly far away).
    private static int? Pixel(double coordinate) =>
        double.IsFinite(coordinate) && Math.Abs(coordinate) < int.MaxValue / 2 ? (int)Math.Floor(coordinate) : null;
}
