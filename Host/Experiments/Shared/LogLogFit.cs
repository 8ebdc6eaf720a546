namespace QuantumRayTracing.Experiments;

/// <summary>The least-squares slope of log10(error) on log10(queries): how fast an error falls, as a fit.</summary>
public static class LogLogFit
{
    /// <summary>The slope over the points with a positive error; NaN with fewer than two.</summary>
    public static double Slope(IEnumerable<(double Queries, double Error)> points)
    {
        var xy = points.Where(p => p.Error > 0).Select(p => (X: Math.Log10(p.Queries), Y: Math.Log10(p.Error))).ToArray();
        if (xy.Length < 2) return double.NaN;
        var (mx, my) = (xy.Average(p => p.X), xy.Average(p => p.Y));
        return xy.Sum(p => (p.X - mx) * (p.Y - my)) / xy.Sum(p => (p.X - mx) * (p.X - mx));
    }
}
