using QuantumRayTracing.Output;
using ScottPlot;

namespace QuantumRayTracing.Benchmarks;

/// <summary>
/// The plots of docs/noise.md, drawn with ScottPlot and written through <see cref="PngWriter"/> (so a later
/// run may replace them). Every plot names its noise model in its title and the machine in a note.
/// </summary>
public static class NoisePlots
{
    private const int Width = 900;
    private const int Height = 520;

    /// <summary>The device experiment's histograms: one group of bars per measured index, one bar per error rate.</summary>
    public static RgbImage Histograms(IReadOnlyList<NoiseBenchmark.DeviceRun> runs, string title, string note)
    {
        var plot = new Plot();
        var palette = new ScottPlot.Palettes.Category10();
        var states = runs[0].Histogram.Length;
        var width = 0.8 / runs.Count;
        for (var k = 0; k < runs.Count; k++)
        {
            var run = runs[k];
            var bars = Enumerable.Range(0, states).Select(i => new Bar
            {
                Position = i - 0.4 + width * (k + 0.5),
                Value = (double)run.Histogram[i] / run.Shots,
                Size = width * 0.9,
                FillColor = palette.GetColor(k),
            }).ToArray();
            plot.Add.Bars(bars);
            plot.Legend.ManualItems.Add(new LegendItem { LabelText = run.PerGate == 0 ? "ideal" : $"p = {run.PerGate:0.#e0}", FillColor = palette.GetColor(k) });
        }
        plot.Add.HorizontalLine(1.0 / states, pattern: LinePattern.Dashed, color: Colors.Gray);
        plot.Axes.Bottom.SetTicks(Enumerable.Range(0, states).Select(i => (double)i).ToArray(), Enumerable.Range(0, states).Select(i => $"|{Convert.ToString(i, 2).PadLeft((int)Math.Log2(states), '0')}⟩").ToArray());
        plot.Axes.SetLimitsY(0, 1.05);
        Finish(plot, title, "measured index", "share of shots", note);
        plot.ShowLegend(Alignment.UpperRight);
        return Render(plot);
    }

    /// <summary>A log-x line plot: each series a list of (x, y) points; x must be positive.</summary>
    public static RgbImage LogX(string title, string xLabel, string yLabel, string note, IReadOnlyList<(string Name, IReadOnlyList<(double X, double Y)> Points)> series, double? horizontal = null, string? horizontalLabel = null)
    {
        var plot = new Plot();
        var palette = new ScottPlot.Palettes.Category10();
        for (var k = 0; k < series.Count; k++)
        {
            var (name, points) = series[k];
            var scatter = plot.Add.Scatter(points.Select(p => Math.Log10(p.X)).ToArray(), points.Select(p => p.Y).ToArray(), palette.GetColor(k));
            scatter.LegendText = name;
            scatter.MarkerSize = 7;
        }
        if (horizontal is { } y)
        {
            var line = plot.Add.HorizontalLine(y, pattern: LinePattern.Dashed, color: Colors.Gray);
            line.LegendText = horizontalLabel ?? "";
        }
        var xs = series.SelectMany(s => s.Points).Select(p => Math.Log10(p.X)).ToArray();
        var ticks = Enumerable.Range((int)Math.Floor(xs.Min()), (int)Math.Ceiling(xs.Max()) - (int)Math.Floor(xs.Min()) + 1).Select(e => (double)e).ToArray();
        plot.Axes.Bottom.SetTicks(ticks, ticks.Select(e => $"1e{e:0}").ToArray());
        Finish(plot, title, xLabel, yLabel, note);
        plot.ShowLegend(Alignment.UpperRight);
        return Render(plot);
    }

    private static void Finish(Plot plot, string title, string xLabel, string yLabel, string note)
    {
        plot.Title(title, 14);
        plot.XLabel(xLabel, 13);
        plot.YLabel(yLabel, 13);
        var annotation = plot.Add.Annotation(note, Alignment.LowerLeft);
        annotation.LabelFontSize = 10;
    }

    private static RgbImage Render(Plot plot) => ImageReader.Decode(plot.GetImageBytes(Width, Height, ImageFormat.Png), "plot");
}
