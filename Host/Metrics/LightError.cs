namespace QuantumRayTracing.Metrics;

/// <summary>
/// The error of estimated light against the exact mean of each shading point's sample set, as sums that add over a render's
/// parts: the squared differences of every point's irradiance channels, their count and the exact values' range.
/// <see cref="Nrmse"/> = √(mean squared difference) / (max − min of the exact values), docs/conventions.md's normalisation on
/// linear irradiance instead of 8-bit pixels.
/// </summary>
public sealed record LightError(double SquaredError, long Values, double Min, double Max)
{
    /// <summary>No values yet (its range is empty and is ignored when added to).</summary>
    public static LightError None => new(0, 0, 0, 0);

    /// <summary>The error with one more value: <paramref name="estimate"/> against <paramref name="exact"/>.</summary>
    public LightError Add(double estimate, double exact) => Add(new LightError((estimate - exact) * (estimate - exact), 1, exact, exact));

    public LightError Add(LightError other) =>
        other.Values == 0 ? this
        : Values == 0 ? other
        : new(SquaredError + other.SquaredError, Values + other.Values, Math.Min(Min, other.Min), Math.Max(Max, other.Max));

    /// <summary>0 when there is nothing to compare or the exact values are all equal and matched.</summary>
    public double Nrmse => Values == 0 ? 0
        : Max > Min ? Math.Sqrt(SquaredError / Values) / (Max - Min)
        : SquaredError == 0 ? 0 : double.PositiveInfinity;
}
