namespace QuantumRayTracing.Estimation;

/// <summary>
/// Where maximum-likelihood amplitude estimation flips its coin: after m = 0 and then m = round(r^j), j = 0, 1, …
/// Grover operators (duplicates dropped), K amplified levels in all; every level gets N flips, the first
/// <see cref="BoostedLevels"/> levels 2N, and the m = 0 level also whatever the budget leaves over.
/// </summary>
/// <param name="Ratio">r, the growth of m from level to level: 2 is Suzuki et al.'s exponential schedule.</param>
/// <param name="BoostedLevels">How many of the lowest levels (m = 0 first) get twice the flips.</param>
/// <param name="MinimumShots">The default K is the largest that keeps N at least this.</param>
public sealed record MlaeSchedule(double Ratio, int BoostedLevels, int MinimumShots)
{
    /// <summary>
    /// The default: r = 1.5, m = 0 and m = 1 doubled, N ≥ 8. Against the doubling schedule it lowers the error from 480
    /// queries up (docs/supersampling.md): each level only has to pick the right peak among those of a level 1.5 times
    /// coarser, so fewer flips per level suffice and the budget reaches higher m.
    /// </summary>
    public static readonly MlaeSchedule Default = new(1.5, 2, 8);

    /// <summary>Suzuki et al.'s exponential schedule m = 0, 1, 2, 4, …, equal flips, N ≥ 12.</summary>
    public static readonly MlaeSchedule Doubling = new(2, 0, 12);

    public const int MaxLevels = 20;

    /// <summary>The Grover operators of each level: 0, then K distinct amplifications.</summary>
    public int[] Iterations(int levels)
    {
        if (levels < 0 || levels > MaxLevels) throw new ArgumentOutOfRangeException(nameof(levels), levels, $"MLAE takes 0 to {MaxLevels} amplified levels");
        var iterations = new List<int> { 0 };
        for (var x = 1.0; iterations.Count <= levels; x *= Ratio)
        {
            var m = (int)Math.Round(x, MidpointRounding.AwayFromZero);
            if (m > iterations[^1]) iterations.Add(m);
        }
        return [.. iterations];
    }

    /// <summary>Flips of level <paramref name="index"/> of <paramref name="levels"/> per unit N: 2 for the boosted lowest levels, else 1 (and 1 with no amplified level, where there is nothing to balance).</summary>
    public int Weight(int index, int levels) => levels > 0 && index < BoostedLevels ? 2 : 1;

    /// <summary>Queries of N = 1: Σ weight_i (1 + 2m_i), the fewest this K can run on.</summary>
    public long QueriesPerShot(int levels) => Iterations(levels).Select((m, i) => Weight(i, levels) * (1 + 2L * m)).Sum();

    /// <summary>The largest K whose levels all get at least <see cref="MinimumShots"/> flips per unit of N.</summary>
    public int DefaultLevels(long queries)
    {
        var levels = 0;
        while (levels < MaxLevels && queries / QueriesPerShot(levels + 1) >= MinimumShots) levels++;
        return levels;
    }
}
