using System.Globalization;

namespace QuantumRayTracing.Export;

/// <summary>
/// The measured register's exact outcome distribution as the QDK computes it (the state vector before the
/// measurement), and the header line that lists its most likely values for checking a run against.
/// </summary>
public sealed record IdealDistribution(IReadOnlyList<double> Probabilities)
{
    /// <summary>Values less likely than this are left off the header line (they are rounding residue, not outcomes).</summary>
    public const double Negligible = 1e-12;

    /// <summary>At most this many values on the header line; the rest are summed on the next line.</summary>
    public const int MaxListed = 64;

    /// <summary>The most likely values, most likely first (ties by value), at most <see cref="MaxListed"/>.</summary>
    public IReadOnlyList<(int Value, double Probability)> MostLikely =>
        Probabilities.Select((p, v) => (Value: v, Probability: p)).Where(e => e.Probability > Negligible)
            .OrderByDescending(e => e.Probability).ThenBy(e => e.Value).Take(MaxListed).ToArray();

    /// <summary>"ideal outcome probabilities: V:P V:P ...", P written to round-trip precision.</summary>
    public string Line => "ideal outcome probabilities: "
        + string.Join(' ', MostLikely.Select(e => $"{e.Value.ToString(CultureInfo.InvariantCulture)}:{e.Probability.ToString("R", CultureInfo.InvariantCulture)}"));

    /// <summary>What the header line leaves off, when anything.</summary>
    public string? Remainder
    {
        get
        {
            var listed = MostLikely;
            var left = Probabilities.Count(p => p > Negligible) - listed.Count;
            return left > 0
                ? $"({left} further values share probability {(1 - listed.Sum(e => e.Probability)).ToString("R", CultureInfo.InvariantCulture)})"
                : null;
        }
    }
}
