using System.Globalization;

namespace QuantumRayTracing.Output.Plots;

/// <summary>
/// Short numeric labels for ticks: plain decimals between 0.001 and a million (0.01, 100, 2.5), and
/// mantissa-e-exponent outside (1e-6, 2.5e7), which stays narrow where plain digits would run long.
/// </summary>
internal static class TickLabels
{
    private const double PlainMin = 1e-3;
    private const double PlainMax = 1e6;

    /// <summary>Whether an axis reaching <paramref name="largestMagnitude"/> at most is labelled in e-notation.</summary>
    public static bool NeedsScientific(double largestMagnitude) => largestMagnitude >= PlainMax || largestMagnitude < PlainMin;

    /// <summary>
    /// The label of <paramref name="value"/>, a multiple of <paramref name="step"/> (1, 2 or 5 times a power of
    /// ten): plain with as many decimals as the step needs, or in e-notation with a mantissa just as precise.
    /// </summary>
    public static string Multiple(double value, double step, bool scientific)
    {
        var stepExponent = (int)Math.Floor(Math.Log10(step) + 1e-9);
        // Zero keeps the decimals of its neighbours (0.0 between -0.5 and 0.5), and never shows as -0.
        if (!scientific) return (value == 0 ? 0 : value).ToString("F" + Math.Clamp(-stepExponent, 0, 15), CultureInfo.InvariantCulture);
        return value == 0 ? "0" : Scientific(value, Math.Clamp(Exponent(value) - stepExponent, 0, 15));
    }

    /// <summary>The shortest label of <paramref name="value"/>, to at most 12 significant digits.</summary>
    public static string Compact(double value)
    {
        if (value == 0) return "0";
        var magnitude = Math.Abs(value);
        if (magnitude >= PlainMin && magnitude < PlainMax)
        {
            // Rounding to significant digits first drops the tail of sums like 0.1 + 0.2.
            var digits = Math.Clamp(11 - Exponent(value), 0, 15);
            return Math.Round(value, digits).ToString("0.###############", CultureInfo.InvariantCulture);
        }
        return Scientific(value, 11);
    }

    /// <summary>
    /// The label of 10^<paramref name="exponent"/>, written from the exponent so powers beyond the double range
    /// (which a log axis padded past 1e308 can reach) still read 1e309 rather than infinity.
    /// </summary>
    public static string PowerOfTen(int exponent) =>
        Math.Pow(10, exponent) is var value && value >= PlainMin && value < PlainMax
            ? Compact(value)
            : "1e" + exponent.ToString(CultureInfo.InvariantCulture);

    // Mantissa with at most `decimals` decimals, trailing zeros dropped: 1e6, 1.5e6, -2e-7.
    private static string Scientific(double value, int decimals)
    {
        var exponent = Exponent(value);
        var mantissa = Math.Round(Shift(value, exponent), decimals);
        if (Math.Abs(mantissa) >= 10)
        {
            exponent++;
            mantissa = Math.Round(Shift(value, exponent), decimals);
        }
        var text = mantissa.ToString("F" + decimals, CultureInfo.InvariantCulture);
        if (text.Contains('.')) text = text.TrimEnd('0').TrimEnd('.');
        return text + "e" + exponent.ToString(CultureInfo.InvariantCulture);
    }

    // value / 10^exponent; below 1e-300 the power itself would underflow, so the value is raised first.
    private static double Shift(double value, int exponent) =>
        exponent < -300 ? value * 1e300 / Math.Pow(10, exponent + 300) : value / Math.Pow(10, exponent);

    private static int Exponent(double value) => (int)Math.Floor(Math.Log10(Math.Abs(value)));
}
