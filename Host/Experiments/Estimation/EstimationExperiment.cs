using QuantumRayTracing.Randomness;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// `bench estimation`: every mean estimator's error against queries, on uniform random means and on the pixels of the
/// Qornell box, without noise and under depolarizing decay per Grover operator (docs/estimation.md).
/// </summary>
public static class EstimationExperiment
{
    /// <summary>One estimator at one budget on one input: the error statistics over its estimates and the queries they spent.</summary>
    /// <param name="Input">"means" or "pixels".</param>
    /// <param name="Decay">γ per Grover operator; 0 without noise.</param>
    /// <param name="Estimator">The estimator's label.</param>
    /// <param name="Budget">Queries allowed per estimate (QSS: its run's count).</param>
    /// <param name="Queries">Queries spent per estimate, on average (docs/conventions.md: a flip 1, a Grover operator 2).</param>
    /// <param name="GroverOperators">Grover operators per estimate, on average: the count the AE papers give.</param>
    /// <param name="Mean">Mean absolute error against the exact mean.</param>
    /// <param name="Median">Median absolute error.</param>
    /// <param name="Percentile95">95th percentile of the absolute error.</param>
    /// <param name="TailShare">The share of estimates whose error exceeds 3 times the median error.</param>
    /// <param name="OnDevice">Measured under the device model (<see cref="EstimationSettings.DeviceRates"/>) instead of <paramref name="Decay"/>.</param>
    public sealed record Point(string Input, double Decay, string Estimator, long Budget, double Queries, double GroverOperators,
        double Mean, double Median, double Percentile95, double TailShare, bool OnDevice = false)
    {
        /// <summary>Measured on the ideal machine.</summary>
        public bool Noiseless => Decay == 0 && !OnDevice;
    }

    /// <summary>The estimators, by label, at a budget (null where the budget cannot run one).</summary>
    public static readonly (string Label, Func<long, IMeanEstimator?> Create)[] Estimators =
    [
        ("MC", q => new MonteCarloEstimator(q)),
        ("QCoin", q => q >= QCoinEstimator.MinimumQueries(1) ? new QCoinEstimator(q, QCoinEstimator.DefaultSteps(q)) : null),
        ("MLAE", q => new MaximumLikelihoodEstimator(q, MaximumLikelihoodEstimator.DefaultLevels(q))),
        ("IQAE", q => new IterativeAmplitudeEstimator(q)),
        ("IQAE, original", q => new IterativeAmplitudeEstimator(q, rerunLastRound: false)),
        ("FAE", q => new FasterAmplitudeEstimator(q)),
        ("BAE", q => new BayesianAmplitudeEstimator(q)),
        ("power-law", q => new PowerLawAmplitudeEstimator(q)),
    ];

    /// <summary>QSS with single-ancilla Bayesian phase estimation: noiseless only (its shot has no noisy or single-qubit-coin form here).</summary>
    public const string QssBayes = "QSS, Bayesian PE";

    /// <summary>The estimators of the noiseless tables: <see cref="Estimators"/> and <see cref="QssBayes"/>.</summary>
    public static readonly (string Label, Func<long, IMeanEstimator?> Create)[] NoiselessEstimators =
        [.. Estimators, (QssBayes, q => new BayesianPhaseEstimator(q))];

    public const string Qss = "QSS";

    /// <summary>Bit-plane QSS (8 planes through the exact lookup table), on the pixels only: it needs the 8-bit subpixels of an image.</summary>
    public const string QssPlanes = "QSS, bit planes";

    public static List<Point> Run(EstimationSettings settings, Action<string> progress)
    {
        var root = new SeededRandom(settings.Seed);
        var random = root.Fork(RandomStreams.Scenario);
        var means = Enumerable.Range(0, settings.Trials).Select(_ => new[] { random.NextDouble() }).ToArray();
        progress($"rendering the Qornell box at {settings.ImageSize * EstimationSettings.Subpixels} pixels per side");
        var image = new SubpixelImage(SupersamplingImageBenchmark.RenderQornell(settings.ImageSize, EstimationSettings.Subpixels), EstimationSettings.Subpixels);
        var pixels = Enumerable.Range(0, image.Pixels).SelectMany(p => Enumerable.Range(0, 3).Select(c => image.Values(p, c))).ToArray();

        var runs = new List<(string Input, double[][] Values, double Decay, string Label, long Budget, Func<IMeanEstimator> Create, bool OnDevice)>();
        foreach (var (input, values) in new[] { ("means", means), ("pixels", pixels) })
        {
            foreach (var budget in EstimationSettings.Budgets)
                foreach (var (label, create) in Estimators)
                    if (create(budget) is not null) runs.Add((input, values, 0, label, budget, () => create(budget)!, false));
            foreach (var t in EstimationSettings.QssCounterBits)
                runs.Add((input, values, 0, Qss, (2L << t) - 1, () => new QssEstimator(t), false));
        }
        foreach (var t in EstimationSettings.PlaneCounterBits)
        {
            var table = QssLookupTable.Exact(image.Count, t);
            runs.Add(("pixels", pixels, 0, QssPlanes, SupersampleSettings.DefaultPlanes * ((2L << t) - 1), () => new BitPlaneQssEstimator(table, SupersampleSettings.DefaultPlanes), false));
        }
        if (settings.Noise)
            foreach (var decay in EstimationSettings.Decays)
                foreach (var budget in EstimationSettings.NoisyBudgets)
                    foreach (var (label, create) in Estimators)
                        if (create(budget) is not null) runs.Add(("means", means, decay, label, budget, () => create(budget)!, false));
        // Last, so every other run keeps its index and so its engine stream.
        foreach (var (input, values) in new[] { ("means", means), ("pixels", pixels) })
            foreach (var budget in EstimationSettings.Budgets)
                runs.Add((input, values, 0, QssBayes, budget, () => new BayesianPhaseEstimator(budget), false));
        // After those, for the same reason: the direct coin at the device's rates.
        if (settings.Noise)
            foreach (var budget in EstimationSettings.NoisyBudgets)
                foreach (var (label, create) in Estimators)
                    if (create(budget) is not null) runs.Add(("means", means, 0, label, budget, () => create(budget)!, true));

        // Each run has its own engine stream, so the points do not depend on the order the two cores take them in.
        var points = new Point[runs.Count];
        var done = 0;
        Parallel.For(0, runs.Count, new ParallelOptions { MaxDegreeOfParallelism = 2 }, i =>
        {
            var run = runs[i];
            var random = root.Fork(RandomStreams.Supersampling + (ulong)i);
            ICoinEngine inner = run.OnDevice
                ? new DirectCoinEngine(new AnalyticCoinEngine(random, device: EstimationSettings.DeviceRates))
                : run.Decay == 0
                    ? new AnalyticCoinEngine(random)
                    : new DirectCoinEngine(new AnalyticCoinEngine(random, Noise.NoiseModel.Depolarizing(NoiseEstimationExperiment.RateForDecay(run.Decay))));
            using var engine = new QueryCountingEngine(inner);
            var estimates = run.Create().Estimate(run.Values, engine);
            var errors = run.Values.Select((v, j) => Math.Abs(estimates[j] - CoinValues.Mean(v))).Order().ToArray();
            var median = Quantile(errors, 0.5);
            points[i] = new Point(run.Input, run.Decay, run.Label, run.Budget, (double)engine.Queries / errors.Length, (double)engine.GroverOperators / errors.Length,
                errors.Average(), median, Quantile(errors, 0.95), errors.Count(e => e > 3 * median) / (double)errors.Length, run.OnDevice);
            var finished = Interlocked.Increment(ref done);
            if (finished % 20 == 0) progress($"{finished} of {runs.Count} points");
        });
        return [.. points];
    }

    /// <summary>The q-quantile of sorted values, interpolated linearly.</summary>
    public static double Quantile(IReadOnlyList<double> sorted, double q)
    {
        var position = q * (sorted.Count - 1);
        var below = (int)Math.Floor(position);
        var above = Math.Min(below + 1, sorted.Count - 1);
        return sorted[below] + (position - below) * (sorted[above] - sorted[below]);
    }

    /// <summary>Least-squares slope of log10(mean error) on log10(queries spent) over the points with budgets in [from, to]: a fit.</summary>
    public static double Slope(IEnumerable<Point> points, long from, long to) =>
        LogLogFit.Slope(points.Where(p => p.Budget >= from && p.Budget <= to).Select(p => (p.Queries, p.Mean)));
}
