namespace QuantumRayTracing.Estimation;

/// <summary>
/// Maximum-likelihood amplitude estimation on a noisy machine (Tanaka et al. 2021, "Amplitude estimation via maximum
/// likelihood on noisy quantum computer"): flips like <see cref="MaximumLikelihoodEstimator"/>'s (by default with an
/// adaptive schedule, below), but the likelihood of a head after m Grover operators is that of a globally depolarized coin,
/// P(head | θ, γ) = Φ · sin²((2m+1)θ) + (1 − Φ) / 2 with Φ = e^(−γ(m+½)), and the decay γ ≥ 0 per Grover operator (the
/// fidelity F = e^(−γ)) is estimated jointly with θ. The estimate is sin²θ.
/// </summary>
/// <remarks>
/// Φ = F^(m+½) counts the flip's 2m+1 applications of the coin's preparation A, each keeping a share √F: the preparation
/// and measurement of an unamplified flip are noisy too (the analytic engine's model has Φ = F₀ · F^m with F₀ close to
/// F^½ for the mean coin, exactly F^½ for the single-qubit direct coin). Plain MLAE reads a level whose coin noise has pulled towards ½ as a θ that gives that contrast, and so errs by an
/// amount more flips do not remove (docs/noise-estimation.md). Here a level the noise has flattened only says little.
/// The search: the log-likelihood on a grid of θ (16 points per unit of 2m+1 at the deepest level, i.e. 32 per period
/// of its fringe) times a grid of γ (0 and 0.001 to 4 in steps of 4), then alternate golden-section refinement of θ
/// within one grid step and of γ between its grid neighbours. The decay is kept only when the likelihood-ratio test finds it
/// (<see cref="NoiseEvidence"/>) and the fit is not at an anomalous mean (<see cref="MlaeFisherInformation.AnomalyFactor"/>);
/// otherwise the flips are read as plain MLAE reads them. The decay carries a prior (<see cref="DecayPenalty"/>), so a
/// large decay needs strong evidence: on a noiseless machine a chance fit of a large decay frees θ to follow the few
/// shallow levels alone, and costs far more than a small one. Deterministic: the same heads give the same estimate. No
/// heads anywhere gives 0 and heads everywhere 1, exactly, as plain MLAE.
/// <para>
/// Adaptive schedule (the default): a fixed schedule spends most of its queries on its deepest levels, which noise
/// flattens first. So the estimator first flips the schedule's shallow levels (the longest prefix within
/// <see cref="SurveyShare"/> of the budget), fits θ and γ to them, and spends the rest of the budget by what it found:
/// with no decay found, on the schedule's remaining levels exactly as plain MLAE (the same levels and flips); with a decay
/// γ̂, on the one level m whose flips lower the Cramér–Rao error of the mean most at (θ̂, γ̂)
/// (<see cref="MlaeFisherInformation.StandardError"/>), any queries left over as unamplified flips. The estimate is the fit
/// to all the flips. Two engine batches; the budget is spent exactly (each flip after m Grover operators costs 1 + 2m).
/// </para>
/// </remarks>
public sealed class NoiseAwareMaximumLikelihoodEstimator : IMeanEstimator
{
    /// <summary>The grid of decays γ per Grover operator the search starts from (F = 1, 0.999, …, 0.018).</summary>
    public static readonly double[] DecayGrid = [0, 0.001, 0.004, 0.016, 0.0625, 0.25, 1, 4];

    private const int PointsPerFactor = 16;

    private const int RefinementRounds = 4;

    /// <summary>
    /// The likelihood-ratio statistic 2·(ln L(θ̂, γ̂) − ln L(θ̂₀, 0)) above which the decay is kept: the 5% point of its
    /// distribution on a noiseless machine (½χ²₀ + ½χ²₁, γ = 0 lying on the boundary). Below it the flips are read as
    /// noiseless, exactly as plain MLAE reads them, so fitting a decay that is not there costs no accuracy.
    /// </summary>
    public const double NoiseEvidence = 5.41;

    /// <summary>
    /// The weight λ of the decay's prior e^(−λγ) (an exponential prior of mean γ = 0.1 per Grover operator): the fit
    /// maximises ln L − λγ, and the likelihood-ratio test counts the penalty against the decay.
    /// </summary>
    public const double DecayPenalty = 10;

    /// <summary>The share of the budget the adaptive schedule spends on the schedule's shallow levels before it estimates the decay.</summary>
    public const double SurveyShare = 0.5;

    private readonly MaximumLikelihoodEstimator _flips;

    /// <param name="queries">The budget per estimate.</param>
    /// <param name="levels">K, amplified levels of the schedule.</param>
    /// <param name="schedule">The schedule; plain MLAE's default when null.</param>
    /// <param name="adaptive">True (default): spend the second share of the budget by the decay the first share shows; false: plain MLAE's flips.</param>
    public NoiseAwareMaximumLikelihoodEstimator(long queries, int levels, MlaeSchedule? schedule = null, bool adaptive = true)
    {
        _flips = new MaximumLikelihoodEstimator(queries, levels, schedule);
        Adaptive = adaptive;
        SurveyLevels = SurveyLength(_flips.Iterations, _flips.Flips, queries);
    }

    /// <summary>Whether the second share of the budget follows the decay the first share shows.</summary>
    public bool Adaptive { get; }

    /// <summary>How many of the schedule's levels (m = 0 first) the adaptive schedule flips before it estimates the decay.</summary>
    public int SurveyLevels { get; }

    public MlaeSchedule Schedule => _flips.Schedule;

    public int Levels => _flips.Levels;

    /// <summary>Grover operators m of each level of the fixed schedule, as plain MLAE's (the adaptive one starts with them).</summary>
    public int[] Iterations => _flips.Iterations;

    /// <summary>Flips of each level of the fixed schedule, as plain MLAE's.</summary>
    public int[] Flips => _flips.Flips;

    public string Name => Adaptive ? $"mlae-noise (K = {Levels}, adaptive)" : $"mlae-noise (K = {Levels})";

    public long Queries => _flips.Queries;

    public IReadOnlyList<double> Estimate(IReadOnlyList<double[]> values, ICoinEngine engine) =>
        Observe(values, engine).Select(levels => Math.Clamp(Math.Pow(Math.Sin(MostLikely(levels).Angle), 2), 0, 1)).ToArray();

    /// <summary>Every item's flips: plain MLAE's schedule, or with <see cref="Adaptive"/> its survey levels and then the rest as <see cref="PlanRest"/> chooses.</summary>
    public IReadOnlyList<MlaeLevel[]> Observe(IReadOnlyList<double[]> values, ICoinEngine engine)
    {
        if (!Adaptive || SurveyLevels == Iterations.Length) return _flips.Flip(values, engine);
        var survey = Enumerable.Range(0, SurveyLevels).Select(l => (Iterations[l], Flips[l])).ToArray();
        var surveyed = Flip(values, values.Select(_ => survey).ToArray(), engine);
        var rest = Queries - survey.Sum(l => (1 + 2L * l.Item1) * l.Item2);
        var plans = surveyed.Select(levels => PlanRest(levels, rest)).ToArray();
        var more = Flip(values, plans, engine);
        return surveyed.Select((levels, j) => levels.Concat(more[j]).ToArray()).ToArray();
    }

    /// <summary>
    /// Where the adaptive schedule spends its <paramref name="rest"/> queries after the survey <paramref name="surveyed"/>:
    /// the fixed schedule's remaining levels when the survey shows no decay, else the level of the schedule's series whose
    /// flips lower the predicted error of the mean most at the surveyed (θ̂, γ̂), and the queries its flips leave as m = 0 flips.
    /// </summary>
    public (int Iterations, int Flips)[] PlanRest(IReadOnlyList<MlaeLevel> surveyed, long rest)
    {
        var (angle, decay) = MostLikely(surveyed);
        if (decay == 0) return [.. Enumerable.Range(SurveyLevels, Iterations.Length - SurveyLevels).Select(l => (Iterations[l], Flips[l]))];
        var mean = Math.Pow(Math.Sin(angle), 2);
        var known = surveyed.Select(o => (o.Iterations, o.Flips)).ToList();
        var (best, bestError) = (0, double.PositiveInfinity);
        foreach (var m in Schedule.Iterations(MlaeSchedule.MaxLevels))
        {
            var flips = rest / (1 + 2L * m);
            if (flips == 0) break;
            var error = MlaeFisherInformation.StandardError(mean, decay, [.. known, (m, (int)flips)]);
            if (error < bestError) (best, bestError) = (m, error);
        }
        var chosen = (int)(rest / (1 + 2L * best));
        var left = (int)(rest - chosen * (1 + 2L * best));
        return left > 0 && best > 0 ? [(best, chosen), (0, left)] : [(best, chosen)];
    }

    // The longest prefix of the schedule (at least m = 0 and the first amplified level) whose flips cost at most SurveyShare of the budget.
    private static int SurveyLength(int[] iterations, int[] flips, long queries)
    {
        var count = Math.Min(2, iterations.Length);
        var spent = Enumerable.Range(0, count).Sum(l => (1 + 2L * iterations[l]) * flips[l]);
        while (count < iterations.Length && spent + (1 + 2L * iterations[count]) * flips[count] <= SurveyShare * queries)
            spent += (1 + 2L * iterations[count]) * flips[count++];
        return count;
    }

    // Flips each item's coin at each (m, flips) of its plan, all in one engine batch.
    private static MlaeLevel[][] Flip(IReadOnlyList<double[]> values, IReadOnlyList<(int Iterations, int Flips)[]> plans, ICoinEngine engine)
    {
        var requests = new List<CoinRequest>();
        for (var j = 0; j < values.Count; j++)
        {
            var amplitudes = CoinValues.MeanCoin(values[j]);
            foreach (var (m, n) in plans[j]) requests.Add(new CoinRequest(CoinKind.Mean, amplitudes, m, n));
        }
        var heads = engine.FlipCoins(requests);
        var next = 0;
        return plans.Select(plan => plan.Select(l => new MlaeLevel(l.Iterations, heads[next++], l.Flips)).ToArray()).ToArray();
    }

    /// <summary>(θ ∈ [0, π/2], γ ≥ 0) maximising the likelihood of the observed levels times the decay's prior.</summary>
    public static (double Angle, double Decay) MostLikely(IReadOnlyList<MlaeLevel> observed)
    {
        if (observed.All(o => o.Heads == 0)) return (0, 0);
        if (observed.All(o => o.Heads == o.Flips)) return (Math.PI / 2, 0);

        var deepest = observed.Max(o => o.Iterations);
        var points = PointsPerFactor * (2 * deepest + 1);
        var step = Math.PI / 2 / points;
        // Φ of every grid decay and level, and each level's cos(2(2m+1)θ) at the current grid point.
        var contrast = DecayGrid.Select(g => observed.Select(o => Kept(g, o.Iterations)).ToArray()).ToArray();
        var fringe = new double[observed.Count];
        var (bestPoint, bestDecay, bestValue) = (0, 0, double.NegativeInfinity);
        for (var point = 0; point <= points; point++)
        {
            for (var l = 0; l < observed.Count; l++) fringe[l] = Math.Cos(2 * (2 * observed[l].Iterations + 1) * point * step);
            for (var d = 0; d < DecayGrid.Length; d++)
            {
                var value = LogLikelihood(observed, fringe, contrast[d]) - DecayPenalty * DecayGrid[d];
                if (value > bestValue) (bestPoint, bestDecay, bestValue) = (point, d, value);
            }
        }

        var (theta, decay) = (bestPoint * step, DecayGrid[bestDecay]);
        var (decayLow, decayHigh) = (DecayGrid[Math.Max(0, bestDecay - 1)], bestDecay + 1 < DecayGrid.Length ? DecayGrid[bestDecay + 1] : 2 * DecayGrid[^1]);
        var window = step;
        for (var round = 0; round < RefinementRounds; round++)
        {
            var fixedDecay = decay;
            theta = GoldenMaximum(t => Penalized(observed, t, fixedDecay), Math.Max(0, theta - window), Math.Min(Math.PI / 2, theta + window), theta);
            var fixedTheta = theta;
            decay = GoldenMaximum(g => Penalized(observed, fixedTheta, g), decayLow, decayHigh, decay);
            window /= 2;
        }
        // The refinement starts at the grid's best point, so it can only tie or improve on it; the check guards rounding.
        if (Penalized(observed, theta, decay) < bestValue) (theta, decay) = (bestPoint * step, DecayGrid[bestDecay]);

        // Keep the noiseless fit (plain MLAE's angle) unless the decay, its prior counted, explains the flips significantly better.
        var noiseless = MaximumLikelihoodEstimator.MostLikelyAngle(observed.Select(o => (2 * o.Iterations + 1, o.Heads, o.Flips)).ToArray());
        var gain = 2 * (Penalized(observed, theta, decay) - LogLikelihood(observed, noiseless, 0));
        if (gain <= NoiseEvidence) return (noiseless, 0);
        // At an anomalous mean the flips hardly tell θ from γ (at f = ½ every level reads ½ whatever the noise), so a fitted
        // decay there is as likely a trade for a wrong θ as noise; plain MLAE's reading of such flips is sound (½ reads as ½).
        var levels = observed.Select(o => (o.Iterations, o.Flips)).ToArray();
        var mean = Math.Pow(Math.Sin(theta), 2);
        var lost = MlaeFisherInformation.StandardError(mean, decay, levels) / MlaeFisherInformation.StandardError(mean, decay, levels, decayKnown: true);
        return lost <= MlaeFisherInformation.AnomalyFactor ? (theta, decay) : (noiseless, 0);
    }

    /// <summary>P(head) after m Grover operators on a coin of angle θ whose Grover operators each keep a share e^(−γ) of the state.</summary>
    public static double HeadProbability(double theta, double decay, int iterations)
    {
        var s = Math.Sin((2 * iterations + 1) * theta);
        var kept = Kept(decay, iterations);
        return Math.Clamp(kept * s * s + (1 - kept) / 2, 0, 1);
    }

    /// <summary>Φ = e^(−γ(m+½)): the share of a flip after m Grover operators that noise leaves ideal.</summary>
    public static double Kept(double decay, int iterations) => Math.Exp(-decay * (iterations + 0.5));

    /// <summary>The log-likelihood of the observed levels at (θ, γ).</summary>
    public static double LogLikelihood(IReadOnlyList<MlaeLevel> observed, double theta, double decay)
    {
        var sum = 0.0;
        foreach (var o in observed) sum += LevelLogLikelihood(o, HeadProbability(theta, decay, o.Iterations));
        return sum;
    }

    // The log-likelihood with the decay's prior: what the fit maximises.
    private static double Penalized(IReadOnlyList<MlaeLevel> observed, double theta, double decay) => LogLikelihood(observed, theta, decay) - DecayPenalty * decay;

    // p = (1 − Φ·cos(2(2m+1)θ)) / 2: the same probability as HeadProbability, from precomputed parts.
    private static double LogLikelihood(IReadOnlyList<MlaeLevel> observed, double[] fringe, double[] contrast)
    {
        var sum = 0.0;
        for (var l = 0; l < observed.Count; l++) sum += LevelLogLikelihood(observed[l], Math.Clamp((1 - contrast[l] * fringe[l]) / 2, 0, 1));
        return sum;
    }

    private static double LevelLogLikelihood(MlaeLevel level, double p)
    {
        // A floor on each probability keeps log(0) finite: an outcome the parameters forbid costs a large, not an infinite, penalty.
        const double floor = 1e-300;
        var sum = 0.0;
        if (level.Heads > 0) sum += level.Heads * Math.Log(Math.Max(p, floor));
        if (level.Flips - level.Heads > 0) sum += (level.Flips - level.Heads) * Math.Log(Math.Max(1 - p, floor));
        return sum;
    }

    // The golden-section maximum of f on [low, high], or the current point where that is no better.
    private static double GoldenMaximum(Func<double, double> f, double low, double high, double current)
    {
        const double ratio = 0.6180339887498949;
        for (var round = 0; round < 50; round++)
        {
            var a = high - ratio * (high - low);
            var b = low + ratio * (high - low);
            if (f(a) < f(b)) low = a;
            else high = b;
        }
        var middle = (low + high) / 2;
        return f(middle) >= f(current) ? middle : current;
    }
}
