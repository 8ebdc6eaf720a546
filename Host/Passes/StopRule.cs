using QuantumRayTracing.Randomness;

namespace QuantumRayTracing.Passes;

/// <summary>
/// The per-ray termination criterion of the paper's sec. 6.2: after sn consecutive searches of a ray
/// that found nothing, trace it again with probability p̄^sn, otherwise stop. p̄ is the estimated
/// probability that one search misses although something is there; draws come from a seeded stream
/// in the fixed order rays are observed.
/// </summary>
public sealed class StopRule(double missProbability, SeededRandom random)
{
    public double MissProbability { get; } = missProbability is >= 0 and <= 1
        ? missProbability
        : throw new ArgumentOutOfRangeException(nameof(missProbability), missProbability, "a probability");

    /// <summary>Whether a ray with <paramref name="misses"/> consecutive empty searches is traced again.</summary>
    public bool Continue(int misses) => misses == 0 || random.NextDouble() < Math.Pow(MissProbability, misses);
}
