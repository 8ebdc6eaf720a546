using ScottPlot;

namespace QuantumRayTracing.Estimates;

/// <summary>The hardware report's plot: runtime of one frame against the number of primitives, one line per qubit model, beside the classical render.</summary>
public static class FramePlots
{
    public const int Width = 1100, Height = 560;

    /// <param name="title">The plot's title.</param>
    /// <param name="primitives">N of each frame, ascending.</param>
    /// <param name="models">Each qubit model's label and its frame runtime in seconds at each N (one processor).</param>
    /// <param name="classicalSeconds">The classical render's wall time at each N on this machine.</param>
    /// <returns>The plot as PNG bytes.</returns>
    public static byte[] RuntimeAgainstPrimitives(string title, IReadOnlyList<int> primitives, IReadOnlyList<(string Label, IReadOnlyList<double> Seconds)> models, IReadOnlyList<double> classicalSeconds)
    {
        var plot = new Plot();
        // Log-log: both axes carry log10 of the values, labelled with the values themselves.
        var xs = primitives.Select(n => Math.Log10(n)).ToArray();
        foreach (var (label, seconds) in models)
        {
            var line = plot.Add.Scatter(xs, seconds.Select(Math.Log10).ToArray());
            line.LegendText = label;
            line.MarkerSize = 6;
        }
        var classical = plot.Add.Scatter(xs, classicalSeconds.Select(Math.Log10).ToArray());
        classical.LegendText = "classical brute force, this machine";
        classical.LineStyle.Pattern = LinePattern.Dashed;
        classical.LineWidth = 2;
        classical.Color = Colors.Black;

        plot.Axes.Bottom.TickGenerator = new ScottPlot.TickGenerators.NumericManual(
            primitives.Select(n => new Tick(Math.Log10(n), n.ToString(System.Globalization.CultureInfo.InvariantCulture))).ToArray());
        plot.Axes.Left.TickGenerator = new ScottPlot.TickGenerators.NumericAutomatic
        {
            IntegerTicksOnly = true,
            MinorTickGenerator = new ScottPlot.TickGenerators.LogMinorTickGenerator(),
            LabelFormatter = PowerOfTen,
        };
        plot.Title(title);
        plot.XLabel("primitives N");
        plot.YLabel("runtime per frame (s)");
        plot.ShowLegend(Edge.Right);
        return plot.GetImageBytes(Width, Height, ImageFormat.Png);
    }

    private static string PowerOfTen(double exponent) => exponent switch
    {
        0 => "1",
        1 => "10",
        _ => $"1e{exponent.ToString("0", System.Globalization.CultureInfo.InvariantCulture)}",
    };
}
