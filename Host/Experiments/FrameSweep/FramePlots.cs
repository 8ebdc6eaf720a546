using QuantumRayTracing.Output;

namespace QuantumRayTracing.Estimates;

/// <summary>The hardware report's plot: runtime of one frame against the number of primitives, one line per qubit model, beside the classical render.</summary>
public static class FramePlots
{
    public const int Width = 1100, Height = 560;

    /// <param name="title">The plot's title.</param>
    /// <param name="primitives">N of each frame, ascending.</param>
    /// <param name="models">Each qubit model's label and its frame runtime in seconds at each N (one processor).</param>
    /// <param name="classicalSeconds">The classical render's wall time at each N on this machine.</param>
    public static PlotSpec RuntimeAgainstPrimitives(string title, IReadOnlyList<int> primitives, IReadOnlyList<(string Label, IReadOnlyList<double> Seconds)> models, IReadOnlyList<double> classicalSeconds)
    {
        PlotSeries Series(string label, IReadOnlyList<double> seconds) => new(label, primitives.Select((n, i) => ((double)n, seconds[i])).ToArray());
        var series = models.Select(m => Series(m.Label, m.Seconds)).Append(Series("classical brute force, this machine", classicalSeconds)).ToArray();
        return new PlotSpec(title, "primitives N", "runtime per frame (s)", AxisScale.Log10, AxisScale.Log10, series, Width, Height);
    }
}
