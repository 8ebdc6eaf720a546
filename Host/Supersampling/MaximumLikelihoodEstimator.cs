namespace QuantumRayTracing.Supersampling;

/// <summary>
/// Maximum-likelihood amplitude estimation with the exponential schedule (Suzuki et al. 2020) on the mean
/// coin and its Grover operator: the coin is flipped N times after each of m = 0, 1, 2, 4, …, 2^(K−1)
/// Grover operators, and θ maximises Π_m sin²((2m+1)θ)^h_m cos²((2m+1)θ)^(N−h_m) over [0, π/2];
/// the estimate is sin²θ. All levels are independent, so the whole estimate is one engine batch.
/// </summary>
/// <remarks>
/// Queries: level m costs N(1 + 2m); N is the largest count the budget allows, and the m = 0 level takes
/// what is left over. The likelihood is searched on a grid finer than its narrowest peak (width ~π/(2m+1)),
/// then refined by golden section around the best grid point. No heads anywhere gives θ = 0 and heads
/// everywhere θ = π/2 exactly, so f = 0 and f = 1 are exact.
/// </remarks>
public sealed class MaximumLikelihoodEstimator : IMeanEstimator
{
    public MaximumLikelihoodEstimator(long queries, int levels)
    {
        if (levels < 0 || levels > 20) throw new ArgumentOutOfRangeException(nameof(levels), levels, "MLAE takes 0 to 20 amplified levels");
        var perShot = QueriesPerShot(levels);
        if (queries < perShot || queries > int.MaxValue)
            throw new ArgumentOutOfRangeException(nameof(queries), queries, $"MLAE with K = {levels} needs at least {perShot} queries");
        Levels = levels;
        Queries = queries;
        Shots = (int)(queries / perShot);
        Iterations = [0, .. Enumerable.Range(0, levels).Select(j => 1 << j)];
    }

    /// <summary>Queries of one flip at every level: Σ (1 + 2m) = K + 1 + 2(2^K − 1).</summary>
    public static long QueriesPerShot(int levels) => levels + 1 + 2 * ((1L << levels) - 1);

    /// <summary>
    /// The default K for a budget: the largest with at least <paramref name="minimumShots"/> flips per level.
    /// Fewer flips leave the likelihood's side peaks unresolved (error-vs-queries experiment, docs/supersampling.md).
    /// </summary>
    public static int DefaultLevels(long queries, int minimumShots = 12)
    {
        var levels = 0;
        while (levels < 20 && queries / QueriesPerShot(levels + 1) >= minimumShots) levels++;
        return levels;
    }

    public int Levels { get; }

    /// <summary>N, flips per level.</summary>
    public int Shots { get; }

    public int[] Iterations { get; }

    public string Name => $"mlae (K = {Levels})";

    public long Queries { get; }

    public IReadOnlyList<double> Estimate(IReadOnlyList<double[]> values, ISupersamplingEngine engine)
    {
        foreach (var v in values) SubpixelValues.Check(v);
        var firstShots = (int)(Queries - (QueriesPerShot(Levels) - 1) * Shots);
        var requests = new List<CoinRequest>();
        foreach (var v in values)
        {
            var amplitudes = SubpixelValues.MeanCoin(v);
            foreach (var m in Iterations) requests.Add(new CoinRequest(CoinKind.Mean, amplitudes, m, m == 0 ? firstShots : Shots));
        }
        var heads = engine.FlipCoins(requests);
        var estimates = new double[values.Count];
        for (var j = 0; j < values.Count; j++)
        {
            var observed = Iterations.Select((m, l) => (Factor: 2 * m + 1, Heads: heads[j * Iterations.Length + l], Flips: requests[j * Iterations.Length + l].Flips)).ToArray();
            estimates[j] = Math.Clamp(Math.Pow(Math.Sin(MostLikelyAngle(observed)), 2), 0, 1);
        }
        return estimates;
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
