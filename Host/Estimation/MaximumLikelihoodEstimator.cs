namespace QuantumRayTracing.Estimation;

/// <summary>
/// Maximum-likelihood amplitude estimation (Suzuki et al. 2020) on the mean coin and its Grover operator: the coin
/// is flipped after each level's m Grover operators (<see cref="MlaeSchedule"/>: by default m = 0, 1, 2, 3, 5, 8, …),
/// and θ maximises Π_m sin²((2m+1)θ)^h_m cos²((2m+1)θ)^(n_m−h_m) over [0, π/2]; the estimate is sin²θ. All levels
/// are independent, so the whole estimate is one engine batch.
/// </summary>
/// <remarks>
/// Queries: level m costs n_m(1 + 2m); N, the flips per unit weight, is the largest the budget allows, and the m = 0
/// level takes what is left over. The likelihood is searched on a grid finer than its narrowest peak (width ~π/(2m+1)),
/// then refined by golden section around the best grid point. No heads anywhere gives θ = 0 and heads everywhere
/// θ = π/2 exactly, so f = 0 and f = 1 are exact.
/// </remarks>
public sealed class MaximumLikelihoodEstimator : IMeanEstimator
{
    public MaximumLikelihoodEstimator(long queries, int levels, MlaeSchedule? schedule = null)
    {
        Schedule = schedule ?? MlaeSchedule.Default;
        Iterations = Schedule.Iterations(levels);
        var perShot = Schedule.QueriesPerShot(levels);
        if (queries < perShot || queries > int.MaxValue)
            throw new ArgumentOutOfRangeException(nameof(queries), queries, $"MLAE with K = {levels} needs at least {perShot} queries");
        Levels = levels;
        Queries = queries;
        Shots = (int)(queries / perShot);
        Flips = Iterations.Select((_, i) => Schedule.Weight(i, levels) * Shots).ToArray();
        Flips[0] += (int)(queries - perShot * Shots);
    }

    /// <summary>The default K for a budget under the default schedule (<see cref="MlaeSchedule.DefaultLevels"/>).</summary>
    public static int DefaultLevels(long queries) => MlaeSchedule.Default.DefaultLevels(queries);

    /// <summary>The fewest queries K levels of the default schedule can run on.</summary>
    public static long QueriesPerShot(int levels) => MlaeSchedule.Default.QueriesPerShot(levels);

    public MlaeSchedule Schedule { get; }

    public int Levels { get; }

    /// <summary>N, flips per unit weight.</summary>
    public int Shots { get; }

    /// <summary>Grover operators m of each level.</summary>
    public int[] Iterations { get; }

    /// <summary>Flips of each level; they spend exactly <see cref="Queries"/>.</summary>
    public int[] Flips { get; }

    public string Name => Schedule == MlaeSchedule.Default ? $"mlae (K = {Levels})" : $"mlae, ratio {Schedule.Ratio} (K = {Levels})";

    public long Queries { get; }

    public IReadOnlyList<double> Estimate(IReadOnlyList<double[]> values, ICoinEngine engine) =>
        Flip(values, engine).Select(levels =>
        {
            var observed = levels.Select(l => (Factor: 2 * l.Iterations + 1, l.Heads, l.Flips)).ToArray();
            return Math.Clamp(Math.Pow(Math.Sin(MostLikelyAngle(observed)), 2), 0, 1);
        }).ToArray();

    /// <summary>
    /// Flips every item's mean coin at every level of the schedule, all in one engine batch, and returns per item the
    /// heads seen at each level. The noise-aware estimator fits the same outcomes with its own likelihood.
    /// </summary>
    public IReadOnlyList<MlaeLevel[]> Flip(IReadOnlyList<double[]> values, ICoinEngine engine)
    {
        foreach (var v in values) CoinValues.Check(v);
        var requests = new List<CoinRequest>();
        foreach (var v in values)
        {
            var amplitudes = CoinValues.MeanCoin(v);
            for (var l = 0; l < Iterations.Length; l++) requests.Add(new CoinRequest(CoinKind.Mean, amplitudes, Iterations[l], Flips[l]));
        }
        var heads = engine.FlipCoins(requests);
        var outcomes = new MlaeLevel[values.Count][];
        for (var j = 0; j < values.Count; j++)
            outcomes[j] = Iterations.Select((m, l) => new MlaeLevel(m, heads[j * Iterations.Length + l], requests[j * Iterations.Length + l].Flips)).ToArray();
        return outcomes;
    }

    /// <summary>θ ∈ [0, π/2] maximising the likelihood of the observed heads at each amplification factor 2m+1.</summary>
    public static double MostLikelyAngle(IReadOnlyList<(int Factor, int Heads, int Flips)> observed)
    {
        if (observed.All(o => o.Heads == 0)) return 0;
        if (observed.All(o => o.Heads == o.Flips)) return Math.PI / 2;
        var widest = observed.Max(o => o.Factor);
        var points = 64 * widest;
        var step = Math.PI / 2 / points;
        var (best, bestValue) = (0, double.NegativeInfinity);
        for (var g = 0; g <= points; g++)
        {
            var value = LogLikelihood(observed, g * step);
            if (value > bestValue) (best, bestValue) = (g, value);
        }
        var (low, high) = (Math.Max(0, (best - 1) * step), Math.Min(Math.PI / 2, (best + 1) * step));
        const double ratio = 0.6180339887498949;
        for (var round = 0; round < 60; round++)
        {
            var a = high - ratio * (high - low);
            var b = low + ratio * (high - low);
            if (LogLikelihood(observed, a) < LogLikelihood(observed, b)) low = a;
            else high = b;
        }
        var refined = (low + high) / 2;
        return LogLikelihood(observed, refined) >= bestValue ? refined : best * step;
    }

    private static double LogLikelihood(IReadOnlyList<(int Factor, int Heads, int Flips)> observed, double theta)
    {
        // A floor on each probability keeps log(0) finite: an outcome the angle forbids costs a large, not an infinite, penalty.
        const double floor = 1e-300;
        var sum = 0.0;
        foreach (var (factor, heads, flips) in observed)
        {
            var s = Math.Sin(factor * theta);
            var p = s * s;
            if (heads > 0) sum += heads * Math.Log(Math.Max(p, floor));
            if (flips - heads > 0) sum += (flips - heads) * Math.Log(Math.Max(1 - p, floor));
        }
        return sum;
    }
}
