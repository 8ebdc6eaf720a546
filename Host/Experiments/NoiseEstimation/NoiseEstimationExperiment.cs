using System.Diagnostics;
using QuantumRayTracing.Metrics;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// `bench noise-estimation`: the QCoin paper's device experiments (fig. 10, fig. 1 right), QSS against QCoin, MLAE and the noisy mean coin, and the noise-aware
/// MLAE, all on the analytic supersampling engine under its global depolarizing model (seeded, so a run is reproducible).
/// Measures only; <see cref="NoiseEstimationReport"/> composes the report.
/// </summary>
public static class NoiseEstimationExperiment
{
    /// <summary>Mean absolute error of QCoin with k steps (k = 0: Monte Carlo) on one coin at one rate and budget, over repeated runs at f = ½.</summary>
    public sealed record StepsPoint(string Coin, double Rate, int Steps, long Queries, double Error);

    /// <summary>Mean absolute error of one estimator at one rate and budget over random pixels, and its standard error where measured (NaN otherwise).</summary>
    public sealed record MethodPoint(double Rate, long Queries, string Method, double Error, double StandardError = double.NaN);

    /// <summary>One fig. 1 image: its label, result and error against the exact average.</summary>
    public sealed record ImageRun(string Label, SupersampleResult Result, SupersampleError Error);

    /// <summary>The noise-aware comparison at one decay: γ, the per-gate error that gives it, its points, and each mean's error at the largest budget.</summary>
    public sealed record AwareSweep(double Decay, double Rate, IReadOnlyList<MethodPoint> Points, IReadOnlyList<(double Mean, double Plain, double Aware)> ByMean);

    /// <summary>Everything measured.</summary>
    public sealed record Result(
        IReadOnlyList<StepsPoint> Steps,
        IReadOnlyList<MethodPoint> Nisq,
        SubpixelImage ImageInput,
        IReadOnlyList<ImageRun> Images,
        IReadOnlyList<AwareSweep> Aware,
        DeviceFigures.Figures Device,
        TimeSpan Elapsed);

    /// <summary>The subpixel values of fig. 10's full coin: 64 subpixels i/63, mean ½.</summary>
    public static readonly double[] FullCoinValues = [.. Enumerable.Range(0, 64).Select(i => i / 63.0)];

    public static Result Run(NoiseEstimationSettings settings, Action<string> progress)
    {
        var clock = Stopwatch.StartNew();
        var streams = new Streams(settings.Seed);
        progress("fig. 10: QCoin at f = 0.5 against k, direct and full coin");
        var steps = Steps(settings, streams);
        progress("QSS against QCoin, MLAE and the noisy mean coin at equal queries against the per-gate error");
        var nisq = Nisq(settings, streams);
        progress("fig. 1: the Qornell box at 8x8 subpixels, 240 queries, under noise");
        var input = new SubpixelImage(SupersamplingImageBenchmark.RenderQornell(settings.ImageSize, 8), 8);
        var images = Images(settings, input, streams);
        progress("noise-aware MLAE against plain MLAE, QCoin and MC");
        var aware = Aware(settings, streams);
        progress("figs. 10, 11 and 12 as the paper has them: the device model fitted to fig. 10, QSS on the three-colour image, qubits and iterations against ε");
        var device = DeviceFigures.Measure(settings, streams.Device, streams.Inputs());
        return new Result(steps, nisq, input, images, aware, device, clock.Elapsed);
    }

    /// <summary>
    /// The per-gate error p at which the engine's noise model gives the direct coin's Grover operator the decay γ, F = e^(−γ):
    /// found by bisection on the model itself, so it follows the model however F depends on p.
    /// </summary>
    public static double RateForDecay(double decay)
    {
        if (decay == 0) return 0;
        var (low, high) = (0.0, 0.5);
        for (var round = 0; round < 100; round++)
        {
            var middle = (low + high) / 2;
            if (DecayOf(CoinKind.Direct, [0.5], middle) < decay) low = middle;
            else high = middle;
        }
        return (low + high) / 2;
    }

    /// <summary>γ per Grover operator of a coin under a per-gate error: −ln F.</summary>
    public static double DecayOf(CoinKind kind, IReadOnlyList<double> amplitudes, double rate) =>
        rate == 0 ? 0 : -Math.Log(SupersamplingNoise.GroverOperatorFidelity(kind, amplitudes, NoiseModel.Depolarizing(rate)));

    // One analytic engine per estimator run, each from its own stream: the runs do not depend on one another's order.
    private sealed class Streams(ulong seed)
    {
        private readonly SeededRandom _root = new(seed);
        private ulong _next = RandomStreams.Supersampling;

        public ICoinEngine Engine(double rate, bool direct = false)
        {
            var engine = new AnalyticCoinEngine(_root.Fork(_next++), rate == 0 ? null : NoiseModel.Depolarizing(rate));
            return direct ? new DirectCoinEngine(engine) : engine;
        }

        public SeededRandom Inputs() => _root.Fork(_next++);

        /// <summary>The single-qubit coins of the paper's device runs under <paramref name="device"/> (null: noiseless).</summary>
        public ICoinEngine Device(DeviceNoiseModel? device) => new DirectCoinEngine(new AnalyticCoinEngine(_root.Fork(_next++), device: device));
    }

    private static double MeanAbsoluteError(IMeanEstimator estimator, IReadOnlyList<double[]> values, ICoinEngine engine)
    {
        using var _ = engine;
        var estimates = estimator.Estimate(values, engine);
        return values.Select((v, j) => Math.Abs(estimates[j] - CoinValues.Mean(v))).Average();
    }

    private static List<StepsPoint> Steps(NoiseEstimationSettings settings, Streams streams)
    {
        var points = new List<StepsPoint>();
        foreach (var (coin, values, direct) in new[] { ("direct", new[] { 0.5 }, true), ("full 8x8", FullCoinValues, false) })
        {
            var trials = Enumerable.Repeat(values, settings.Trials).ToArray();
            foreach (var rate in NoiseEstimationSettings.StepRates)
                foreach (var queries in NoiseEstimationSettings.StepBudgets)
                    for (var k = 0; k <= 7; k++)
                    {
                        if (k > 0 && queries < QCoinEstimator.MinimumQueries(k)) continue;
                        IMeanEstimator estimator = k == 0 ? new MonteCarloEstimator(queries) : new QCoinEstimator(queries, k);
                        points.Add(new StepsPoint(coin, rate, k, queries, MeanAbsoluteError(estimator, trials, streams.Engine(rate, direct))));
                    }
        }
        return points;
    }

    /// <summary>The comparison's baselines: classical Monte Carlo without noise, and the floor every estimator must beat.</summary>
    public const string ClassicalMonteCarlo = "classical MC", AlwaysHalf = "always ½";

    /// <summary>The estimators of the comparison under noise at QSS's budget for <paramref name="counterBits"/>, 2^(t+1) − 1 queries.</summary>
    public static IEnumerable<(string Method, IMeanEstimator Estimator)> NisqEstimators(int counterBits)
    {
        var queries = QssRequest.QueriesPerRun(counterBits);
        yield return ("MC", new MonteCarloEstimator(queries));
        yield return ("QSS", new QssEstimator(counterBits));
        yield return ("QCoin", new QCoinEstimator(queries, QCoinEstimator.DefaultSteps(queries)));
        yield return ("MLAE", new MaximumLikelihoodEstimator(queries, MaximumLikelihoodEstimator.DefaultLevels(queries)));
        yield return ("MLAE-noise", new NoiseAwareMaximumLikelihoodEstimator(queries, MaximumLikelihoodEstimator.DefaultLevels(queries)));
    }

    private static List<MethodPoint> Nisq(NoiseEstimationSettings settings, Streams streams)
    {
        var random = streams.Inputs();
        var pixels = Enumerable.Range(0, settings.Trials)
            .Select(_ => Enumerable.Range(0, NoiseEstimationSettings.NisqSubpixels).Select(_ => random.NextDouble()).ToArray()).ToArray();
        var points = new List<MethodPoint>();
        // The baselines every rate's row shows: classical Monte Carlo (the noiseless engine's samples) and always answering ½.
        var half = pixels.Average(v => Math.Abs(0.5 - CoinValues.Mean(v)));
        var classical = NoiseEstimationSettings.NisqCounterBits.Select(QssRequest.QueriesPerRun)
            .ToDictionary(q => q, q => MeanAbsoluteError(new MonteCarloEstimator(q), pixels, streams.Engine(0)));
        foreach (var rate in NoiseEstimationSettings.NisqRates)
            foreach (var t in NoiseEstimationSettings.NisqCounterBits)
            {
                var queries = QssRequest.QueriesPerRun(t);
                points.Add(new MethodPoint(rate, queries, ClassicalMonteCarlo, classical[queries]));
                foreach (var (method, estimator) in NisqEstimators(t))
                    points.Add(new MethodPoint(rate, estimator.Queries, method, MeanAbsoluteError(estimator, pixels, streams.Engine(rate))));
                points.Add(new MethodPoint(rate, queries, AlwaysHalf, half));
            }
        return points;
    }

    private static List<ImageRun> Images(NoiseEstimationSettings settings, SubpixelImage input, Streams streams)
    {
        const long queries = SupersampleSettings.DefaultQueries;
        var full = NoiseEstimationSettings.StepRates.Where(r => r > 0).Min();
        var runs = new (string Label, IMeanEstimator Estimator, double Rate, bool Direct)[]
        {
            ("MC, noiseless", new MonteCarloEstimator(queries), 0, false),
            ("QCoin k=3, noiseless", new QCoinEstimator(queries, 3), 0, false),
            ($"MC, direct coin, p = {settings.DeviceRate:0.#e0}", new MonteCarloEstimator(queries), settings.DeviceRate, true),
            ($"QCoin k=3, direct coin, p = {settings.DeviceRate:0.#e0}", new QCoinEstimator(queries, 3), settings.DeviceRate, true),
            ($"QCoin k=3, full coin, p = {full:0.#e0}", new QCoinEstimator(queries, 3), full, false),
        };
        return runs.Select(r =>
        {
            using var engine = streams.Engine(r.Rate, r.Direct);
            var result = ImageSupersampler.Run(input, r.Estimator, engine);
            return new ImageRun(r.Label, result, SupersampleError.Of(input, result));
        }).ToList();
    }

    private static List<AwareSweep> Aware(NoiseEstimationSettings settings, Streams streams)
    {
        var random = streams.Inputs();
        var means = Enumerable.Range(0, settings.Trials).Select(_ => new[] { random.NextDouble() }).ToArray();
        var sweeps = new List<AwareSweep>();
        foreach (var decay in NoiseEstimationSettings.AwareDecays)
        {
            var rate = RateForDecay(decay);
            var points = new List<MethodPoint>();
            IReadOnlyList<double> plainLast = [], awareLast = [];
            foreach (var queries in NoiseEstimationSettings.AwareBudgets)
            {
                var levels = MaximumLikelihoodEstimator.DefaultLevels(queries);
                foreach (var (method, estimator) in new (string, IMeanEstimator)[]
                {
                    ("MC", new MonteCarloEstimator(queries)),
                    ("QCoin", new QCoinEstimator(queries, QCoinEstimator.DefaultSteps(queries))),
                    ("MLAE", new MaximumLikelihoodEstimator(queries, levels)),
                    ("MLAE-noise", new NoiseAwareMaximumLikelihoodEstimator(queries, levels)),
                })
                {
                    using var engine = streams.Engine(rate, direct: true);
                    var estimates = estimator.Estimate(means, engine);
                    var errors = means.Select((v, j) => Math.Abs(estimates[j] - v[0])).ToArray();
                    var error = errors.Average();
                    var spread = Math.Sqrt(errors.Sum(e => (e - error) * (e - error)) / (errors.Length - 1));
                    points.Add(new MethodPoint(rate, queries, method, error, spread / Math.Sqrt(errors.Length)));
                    if (queries == NoiseEstimationSettings.AwareBudgets[^1] && method == "MLAE") plainLast = estimates;
                    if (queries == NoiseEstimationSettings.AwareBudgets[^1] && method == "MLAE-noise") awareLast = estimates;
                }
            }
            var byMean = means.Select((v, j) => (v[0], Math.Abs(plainLast[j] - v[0]), Math.Abs(awareLast[j] - v[0]))).ToArray();
            sweeps.Add(new AwareSweep(decay, rate, points, byMean));
        }
        return sweeps;
    }
}
