using QuantumRayTracing.Randomness;

namespace QuantumRayTracing.Passes;

/// <summary>
/// The per-ray termination criterion of the paper's sec. 6.2: after sn consecutive searches of a ray
/// that found nothing, trace it again with probability p̄^sn, otherwise stop. p̄ is the estimated
/// probability that one search misses although something is there; draws come from a seeded stream
/// in the fixed order rays are observed. A ray its lattice neighbours do not vouch for first needs
/// <see cref="RequiredMisses"/> consecutive empty searches before the rule may stop it: where nothing
/// predicts the result, the search alone must keep the chance of a missed closer hit within the
/// accuracy budget.
/// </summary>
public sealed class StopRule(double missProbability, SeededRandom random, int requiredMisses = 1, int? budgetMisses = null)
{
    public double MissProbability { get; } = missProbability is >= 0 and <= 1
        ? missProbability
        : throw new ArgumentOutOfRangeException(nameof(missProbability), missProbability, "a probability");

    /// <summary>Consecutive empty searches a ray not vouched for gets before the probabilistic rule applies (at least 1).</summary>
    public int RequiredMisses { get; } = Math.Max(1, requiredMisses);

    /// <summary>
    /// The consecutive empty searches an accuracy budget is expected to ask of a ray nobody vouches for, the stop rule's
    /// or the budget rounds' (at least <see cref="RequiredMisses"/>): what the classical settle weighs against N.
    /// </summary>
    public int BudgetMisses { get; } = Math.Max(Math.Max(1, requiredMisses), budgetMisses ?? 1);

    /// <summary>
    /// Whether a ray with <paramref name="misses"/> consecutive empty searches is traced again;
    /// <paramref name="vouched"/>: its lattice neighbours agreed on its result.
    /// </summary>
    public bool Continue(int misses, bool vouched = false) =>
        misses == 0 || (!vouched && misses < RequiredMisses) || random.NextDouble() < Math.Pow(MissProbability, misses);
}
