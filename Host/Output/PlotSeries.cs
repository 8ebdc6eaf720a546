namespace QuantumRayTracing.Output;

/// <summary>
/// One named set of points. Lines: connect points in order; Markers: draw a marker at each point.
/// A point that cannot be shown (a non-finite coordinate, or a value that is not positive on a log axis)
/// is skipped, and the line breaks there rather than bridging the gap.
/// </summary>
public sealed record PlotSeries(string Label, IReadOnlyList<(double X, double Y)> Points, bool Lines = true, bool Markers = true);
