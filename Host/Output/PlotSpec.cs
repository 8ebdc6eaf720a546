namespace QuantumRayTracing.Output;

/// <summary>
/// Everything <see cref="PlotImage.Render(PlotSpec)"/> draws: title, axis labels and scales, the series (coloured and
/// marked in order) and the image size in pixels.
/// </summary>
public sealed record PlotSpec(string Title, string XLabel, string YLabel, AxisScale XScale, AxisScale YScale,
    IReadOnlyList<PlotSeries> Series, int Width = 800, int Height = 500);
