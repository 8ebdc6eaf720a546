using QuantumRayTracing.Output;
using ScottPlot;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// The plots of docs/noise.md: the line plots as <see cref="PlotSpec"/>s, which the report writer draws like every other
/// plot, the device histograms (bars, which a <see cref="PlotSpec"/> does not describe) drawn with ScottPlot directly. Every plot names its
/// noise model in its title; the report beside them names the machine.
/// </summary>
public static class NoisePlots
{
    private const int Width = 900;
    private const int Height = 520;

    // Wider than the histograms: the legend sits beside the data and the titles are long.
    private const int LinePlotWidth = 1100;

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

    /// <summary>
    /// A line plot against the per-gate error on a log axis: each series a list of (p, y) points with p > 0, and
    /// optionally a labelled horizontal reference line across them.
    /// </summary>
    public static PlotSpec LogX(string title, string xLabel, string yLabel, IReadOnlyList<(string Name, IReadOnlyList<(double X, double Y)> Points)> series, double? horizontal = null, string? horizontalLabel = null)
    {
        var lines = series.Select(s => new PlotSeries(s.Name, s.Points)).ToList();
        var xs = series.SelectMany(s => s.Points).Select(p => p.X).ToArray();
        if (horizontal is { } y && xs.Length > 0)
            lines.Add(new PlotSeries(horizontalLabel ?? "", [(xs.Min(), y), (xs.Max(), y)], Markers: false));
        return new PlotSpec(title, xLabel, yLabel, AxisScale.Log10, AxisScale.Linear, lines, LinePlotWidth, Height);
    }

    private static void Finish(Plot plot, string title, string xLabel, string yLabel, string note)
    {
        plot.Title(title, 14);
        plot.XLabel(xLabel, 13);
        plot.YLabel(yLabel, 13);
        var annotation = plot.Add.Annotation(note, Alignment.LowerLeft);
        annotation.LabelFontSize = 10;
    }

    private static RgbImage Render(Plot plot) => PlotImage.Render(plot, Width, Height);
}
