namespace QuantumRayTracing.Output.Plots;

/// <summary>
/// The colour and marker of each series, by its index in <see cref="PlotSpec.Series"/>. Both cycle; with
/// eight colours and seven shapes (coprime counts) no colour-and-shape pair repeats within 56 series.
/// </summary>
public static class PlotPalette
{
    /// <summary>Saturated, mutually distinct colours, all far from the white background and the grey grid.</summary>
    public static IReadOnlyList<PlotColour> Colours { get; } =
    [
        new(31, 98, 196),   // blue
        new(232, 118, 14),  // orange
        new(36, 150, 62),   // green
        new(204, 36, 44),   // red
        new(126, 76, 180),  // purple
        new(138, 86, 52),   // brown
        new(218, 72, 162),  // pink
        new(16, 154, 164),  // teal
    ];

    /// <summary>Marker shapes in the order series use them.</summary>
    public static IReadOnlyList<MarkerShape> Markers { get; } = Enum.GetValues<MarkerShape>();

    /// <summary>The colour of series number <paramref name="index"/> (0-based).</summary>
    public static PlotColour ColourFor(int index) => Colours[Cycle(index, Colours.Count)];

    /// <summary>The marker of series number <paramref name="index"/> (0-based).</summary>
    public static MarkerShape MarkerFor(int index) => Markers[Cycle(index, Markers.Count)];

    private static int Cycle(int index, int count)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(index);
        return index % count;
    }
}
