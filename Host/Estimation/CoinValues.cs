namespace QuantumRayTracing.Estimation;

/// <summary>Checks and converts a pixel's subpixel values F(i) into the amplitudes the coins take.</summary>
public static class CoinValues
{
    /// <summary>Throws unless there is at least one value and every value lies in [0, 1].</summary>
    public static void Check(double[] values)
    {
        if (values.Length == 0) throw new ArgumentException("a pixel needs at least one subpixel value");
        foreach (var v in values)
            if (!(v >= 0 && v <= 1)) throw new ArgumentOutOfRangeException(nameof(values), v, "subpixel values must lie in [0, 1]");
    }

    /// <summary>√F(i): the mean coin then has head probability f.</summary>
    public static double[] MeanCoin(double[] values) => values.Select(Math.Sqrt).ToArray();

    /// <summary>F(i) − E, QCoin's Q_{F,E}: the shifted coin's head amplitude is f − E.</summary>
    public static double[] Shifted(double[] values, double shift) => values.Select(v => Math.Clamp(v - shift, -1, 1)).ToArray();

    public static double Mean(double[] values) => values.Average();
}
