using MathNet.Numerics.Distributions;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// A fitted convergence line log10(error) = <paramref name="Intercept"/> + <paramref name="Slope"/> · log10(queries): each
/// seed's least-squares line over its query counts, averaged over the seeds (with every seed at the same query counts this is
/// the least-squares line through all the seeds' points). <paramref name="HalfWidth"/> is the 95 % Student-t interval of the
/// mean slope over the seeds' slopes (null with one seed).
/// </summary>
public sealed record ConvergenceFit(double Slope, double? HalfWidth, double Intercept, IReadOnlyList<double> SeedSlopes)
{
    /// <summary>The fit over each seed's (queries, error) points; null when no seed has two distinct query counts with a positive error.</summary>
    public static ConvergenceFit? Of(IEnumerable<IEnumerable<(double Queries, double Error)>> seeds)
    {
        var lines = seeds.Select(LogLogFit.Of).OfType<PowerLawFit>().ToArray();
        if (lines.Length == 0) return null;
        var slopes = lines.Select(l => l.Exponent).ToArray();
        var mean = slopes.Average();
        double? halfWidth = null;
        if (slopes.Length > 1)
        {
            var deviation = Math.Sqrt(slopes.Sum(s => (s - mean) * (s - mean)) / (slopes.Length - 1));
            halfWidth = StudentT.InvCDF(0, 1, slopes.Length - 1, 0.975) * deviation / Math.Sqrt(slopes.Length);
        }
        return new ConvergenceFit(mean, halfWidth, lines.Average(l => l.Intercept), slopes);
    }

    /// <summary>The error the line gives at <paramref name="queries"/>.</summary>
    public double At(double queries) => Math.Pow(10, Intercept + Slope * Math.Log10(queries));

    /// <summary>The queries at which the line reaches <paramref name="error"/>; null when the line does not fall.</summary>
    public double? QueriesTo(double error) => Slope < 0 ? Math.Pow(10, (Math.Log10(error) - Intercept) / Slope) : null;

    /// <summary>
    /// The error at which this line needs <paramref name="ratio"/> times the queries <paramref name="other"/> needs for the same
    /// error; null when either line does not fall or their slopes are equal.
    /// </summary>
    public double? ErrorAtQueriesRatio(ConvergenceFit other, double ratio)
    {
        ArgumentNullException.ThrowIfNull(other);
        if (Slope >= 0 || other.Slope >= 0 || Slope == other.Slope) return null;
        // log10 Q = (log10 e − intercept) / slope on each line; the difference of the two is log10 ratio.
        var log = (Math.Log10(ratio) + Intercept / Slope - other.Intercept / other.Slope) / (1 / Slope - 1 / other.Slope);
        return Math.Pow(10, log);
    }
}
