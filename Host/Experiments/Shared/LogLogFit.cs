namespace QuantumRayTracing.Experiments;

/// <summary>Least-squares fits of log y on log x: how fast a measure grows or falls, as a fit (a power law y = a · x^b).</summary>
public static class LogLogFit
{
    /// <summary>The slope of log10(error) on log10(queries) over the points with a positive error; NaN with fewer than two.</summary>
    public static double Slope(IEnumerable<(double Queries, double Error)> points) => Of(points)?.Exponent ?? double.NaN;

    /// <summary>The fitted power law over the points with positive x and y; null with fewer than two distinct x.</summary>
    public static PowerLawFit? Of(IEnumerable<(double X, double Y)> points)
    {
        var kept = points.Where(p => p.X > 0 && p.Y > 0).ToArray();
        var xy = kept.Select(p => (X: Math.Log10(p.X), Y: Math.Log10(p.Y))).ToArray();
        if (xy.Length < 2) return null;
        var (mx, my) = (xy.Average(p => p.X), xy.Average(p => p.Y));
        var spread = xy.Sum(p => (p.X - mx) * (p.X - mx));
        if (spread == 0) return null;
        var slope = xy.Sum(p => (p.X - mx) * (p.Y - my)) / spread;
        var intercept = my - slope * mx;
        var residual = Math.Sqrt(xy.Average(p => Math.Pow(p.Y - (intercept + slope * p.X), 2)));
        return new PowerLawFit(slope, intercept, residual, kept.Min(p => p.X), kept.Max(p => p.X));
    }
}

/// <summary>
/// y ≈ 10^Intercept · x^Exponent, fitted over x in [<paramref name="From"/>, <paramref name="To"/>]; <paramref name="Residual"/>
/// the root-mean-square of the fit's residuals in log10 (0.1 is a factor of 1.26 either way).
/// </summary>
public sealed record PowerLawFit(double Exponent, double Intercept, double Residual, double From, double To)
{
    public double At(double x) => Math.Pow(10, Intercept + Exponent * Math.Log10(x));

    /// <summary>Where this fit and <paramref name="other"/> meet (x > 0), or null when they are parallel.</summary>
    public double? Crossing(PowerLawFit other)
    {
        ArgumentNullException.ThrowIfNull(other);
        var slopes = Exponent - other.Exponent;
        return Math.Abs(slopes) < 1e-12 ? null : Math.Pow(10, (other.Intercept - Intercept) / slopes);
    }
}
