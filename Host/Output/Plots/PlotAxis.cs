namespace QuantumRayTracing.Output.Plots;

/// <summary>
/// One axis of a laid-out plot: the data range it shows and where that range lies in pixels. Positions are
/// continuous pixel coordinates (pixel x covers [x, x + 1)); <see cref="Min"/> maps to
/// <see cref="PixelAtMin"/> and <see cref="Max"/> to <see cref="PixelAtMax"/>, linearly in the value or, on a
/// <see cref="AxisScale.Log10"/> axis, in its base-10 logarithm.
/// </summary>
public sealed class PlotAxis
{
    // The range in axis units: the values themselves, or their logarithms. Logarithms are kept rather than
    // recomputed from Min and Max, which can underflow to 0 for ranges near the smallest doubles.
    private readonly double _low;
    private readonly double _high;

    internal PlotAxis(AxisScale scale, (double Low, double High) range, double pixelAtMin, double pixelAtMax)
    {
        Scale = scale;
        (_low, _high) = range;
        PixelAtMin = pixelAtMin;
        PixelAtMax = pixelAtMax;
    }

    /// <summary>Linear or logarithmic.</summary>
    public AxisScale Scale { get; }

    /// <summary>The smallest value shown, at <see cref="PixelAtMin"/>.</summary>
    public double Min => Scale == AxisScale.Log10 ? Math.Pow(10, _low) : _low;

    /// <summary>The largest value shown, at <see cref="PixelAtMax"/>.</summary>
    public double Max => Scale == AxisScale.Log10 ? Math.Pow(10, _high) : _high;

    /// <summary>Where <see cref="Min"/> lies: the left edge of the plot area for x, the bottom edge for y.</summary>
    public double PixelAtMin { get; }

    /// <summary>Where <see cref="Max"/> lies: the right edge of the plot area for x, the top edge for y.</summary>
    public double PixelAtMax { get; }

    /// <summary>The ticks, set once by the layout.</summary>
    internal IReadOnlyList<Tick> Ticks { get; set; } = [];

    internal double Low => _low;
    internal double High => _high;
    internal double PixelLength => Math.Abs(PixelAtMax - PixelAtMin);

    /// <summary>
    /// The pixel coordinate of <paramref name="value"/>, or NaN when this axis cannot show it (not finite, or
    /// not positive on a log axis). Values outside the range map outside the plot area.
    /// </summary>
    public double ToPixel(double value) => TryToAxisUnits(Scale, value, out var at) ? PixelOf(at) : double.NaN;

    /// <summary>The pixel coordinate of a position in axis units.</summary>
    internal double PixelOf(double at)
    {
        // Halved before subtracting, so ranges spanning most of the doubles do not overflow.
        var t = (at / 2 - _low / 2) / (_high / 2 - _low / 2);
        return PixelAtMin + t * (PixelAtMax - PixelAtMin);
    }

    /// <summary>
    /// <paramref name="value"/> in axis units: itself on a linear axis, its logarithm on a log axis; false when
    /// the axis cannot show it.
    /// </summary>
    internal static bool TryToAxisUnits(AxisScale scale, double value, out double at)
    {
        at = scale == AxisScale.Log10 ? (value > 0 ? Math.Log10(value) : double.NaN) : value;
        return double.IsFinite(at);
    }

    /// <summary>
    /// The range an axis shows for data at <paramref name="ats"/> (axis units): from the smallest to the largest
    /// with 5% of the span added at each end. A single value gets a range around it (half a decade each way on a
    /// log axis); no data gets 0 to 1 (1 to 10 on a log axis).
    /// </summary>
    internal static (double Low, double High) RangeOf(IReadOnlyCollection<double> ats, AxisScale scale)
    {
        if (ats.Count == 0) return (0, 1);
        double low = ats.Min(), high = ats.Max();
        if (low == high)
        {
            var pad = scale == AxisScale.Log10 ? 0.5 : low == 0 ? 1 : Math.Abs(low) / 10;
            (low, high) = (low - pad, high + pad);
        }
        else
        {
            var pad = (high / 2 - low / 2) / 10;
            (low, high) = (low - pad, high + pad);
        }
        low = Math.Max(low, -double.MaxValue);
        high = Math.Min(high, double.MaxValue);
        // A pad below the spacing of doubles at this magnitude adds nothing; the range must still be open.
        if (!(high > low)) (low, high) = (Math.BitDecrement(low), Math.BitIncrement(high));
        return (low, high);
    }
}
