namespace QuantumRayTracing.Estimation;

/// <summary>
/// Power-law amplitude estimation (Giurgica-Tiron, Kerenidis, Labib, Prakash and Zeng, "Low depth algorithms for quantum
/// amplitude estimation", Quantum 6, 745, 2022): the flips of the k-th step, k = 0, 1, 2, …, <see cref="FlipsPerK"/> of them, follow m_k = ⌊k^((1 − β) / (2β))⌋ Grover
/// operators, and the estimate maximises the likelihood of all the flips (<see cref="MaximumLikelihoodEstimator.MostLikelyAngle"/>).
/// β ∈ (0, 1] trades queries against depth: the error falls as queries^(−1/(1+β)) while the deepest circuit grows as
/// queries^((1−β)/(1+β)), so β → 0 approaches the Heisenberg scaling and β = 1 is Monte Carlo's (every m_k = 1).
/// </summary>
/// <remarks>
/// Budget: the schedule runs as far as the budget pays for every flip of it (a flip after m operators costs 1 + 2m); the
/// queries left over become unamplified flips, so the budget is spent exactly. Flips at the same m are one level, and
/// all levels are one engine batch.
/// </remarks>
public sealed class PowerLawAmplitudeEstimator : IMeanEstimator
{
    /// <summary>The default β (measured, docs/supersampling.md).</summary>
    public const double DefaultBeta = 0.3;

    /// <summary>The default flips per k: one flip per k leaves the likelihood with rival peaks at small budgets (measured, docs/supersampling.md).</summary>
    public const int DefaultShots = 2;

    public PowerLawAmplitudeEstimator(long queries, double beta = DefaultBeta, int? flipsPerK = null)
    {
        if (!(beta > 0 && beta <= 1)) throw new ArgumentOutOfRangeException(nameof(beta), beta, "power-law AE takes β in (0, 1]");
        if (queries < 1 || queries > int.MaxValue) throw new ArgumentOutOfRangeException(nameof(queries), queries, "an estimate needs at least one query");
        var shots = flipsPerK ?? DefaultShots;
        if (shots < 1) throw new ArgumentOutOfRangeException(nameof(flipsPerK), shots, "power-law AE needs at least one flip per k");
        Beta = beta;
        FlipsPerK = shots;
        Queries = queries;
        var levels = new SortedDictionary<int, int>();
        var spent = 0L;
        for (var k = 0; ; k++)
        {
            var m = Depth(k, beta);
            if (spent + shots * (1 + 2L * m) > queries) break;
            spent += shots * (1 + 2L * m);
            levels[m] = levels.GetValueOrDefault(m) + shots;
        }
        levels[0] = levels.GetValueOrDefault(0) + (int)(queries - spent);
        Levels = [.. levels.Select(l => (l.Key, l.Value))];
    }

    /// <summary>m_k = ⌊k^((1 − β) / (2β))⌋, with m_0 = 0.</summary>
    public static int Depth(int k, double beta) => k == 0 ? 0 : (int)Math.Min(int.MaxValue / 4, Math.Floor(Math.Pow(k, (1 - beta) / (2 * beta)) + 1e-9));

    public double Beta { get; }

    /// <summary>Flips at each k of the schedule (default <see cref="DefaultShots"/>).</summary>
    public int FlipsPerK { get; }

    /// <summary>(m, flips) of each distinct depth; they spend exactly <see cref="Queries"/>.</summary>
    public (int Iterations, int Flips)[] Levels { get; }

    public string Name => $"powerlaw (β = {Beta:0.###})";

    public long Queries { get; }

    public IReadOnlyList<double> Estimate(IReadOnlyList<double[]> values, ICoinEngine engine)
    {
        foreach (var v in values) CoinValues.Check(v);
        var requests = values.SelectMany(v =>
        {
            var amplitudes = CoinValues.MeanCoin(v);
            return Levels.Select(l => new CoinRequest(CoinKind.Mean, amplitudes, l.Iterations, l.Flips));
        }).ToArray();
        var heads = engine.FlipCoins(requests);
        return values.Select((_, j) =>
        {
            var observed = Levels.Select((l, i) => (2 * l.Iterations + 1, heads[j * Levels.Length + i], l.Flips)).ToArray();
            return Math.Clamp(Math.Pow(Math.Sin(MaximumLikelihoodEstimator.MostLikelyAngle(observed)), 2), 0, 1);
        }).ToArray();
    }
}
