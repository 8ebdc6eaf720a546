namespace QuantumRayTracing.Shading;

/// <summary>
/// How <c>count</c> samples split the unit square into equal cells: rows the largest divisor of count
/// not above its square root, columns count / rows (32 → 8 x 4; a prime count → one row). Sample s
/// lies in cell (s mod columns, s div columns).
/// </summary>
public static class Strata
{
    public static (int Columns, int Rows) Split(int count)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(count, 1);
        var rows = (int)Math.Sqrt(count);
        while (count % rows != 0) rows--;
        return (count / rows, rows);
    }

    /// <summary>The point of sample <paramref name="sample"/> in [0, 1)² given its jitter in its cell.</summary>
    public static (double U, double V) Point(int sample, int columns, int rows, double jitterU, double jitterV)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(sample);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(sample, columns * rows);
        return ((sample % columns + jitterU) / columns, (sample / columns + jitterV) / rows);
    }
}
