using QuantumRayTracing.Noise;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// The QCoin paper's figs. 10, 11 and 12 as the paper has them: fig. 10 (QCoin at f = ½ on the single-qubit coin against
/// queries for k = 0..7) under a device model fitted to the paper's two observations, fig. 11 (QSS with 7 queries on a
/// three-colour image) under that model with two-qubit gate noise, and fig. 12 (register qubits and amplitude
/// amplification iterations against the error, without noise). Analytic supersampling engine, seeded.
/// </summary>
public static class DeviceFigures
{
    /// <summary>Fig. 10 (left): MC's error on the device stops falling beyond about this many queries (the paper's text).</summary>
    public const long PaperPlateauQueries = 100;

    /// <summary>P(read 1 | 0) assumed for the fit: the paper gives no readout rates, and at f = ½ only P1 − P0 biases k = 0.</summary>
    public const double AssumedReadZeroAsOne = 0.02;

    /// <summary>The one-qubit rates the fit scans for the best k.</summary>
    public static readonly double[] FitOneQubitRates = [1e-3, 2e-3, 3e-3, 5e-3, 7e-3, 1e-2, 1.5e-2, 2e-2];

    /// <summary>Fig. 11: two-qubit rates per qubit swept; 0.0253 makes a two-qubit gate fail with probability 1 − (1 − p)² = 5 %.</summary>
    public static readonly double[] FigureElevenTwoQubitRates = [0, 1e-2, 0.0253, 5e-2];

    /// <summary>Fig. 11's pixel colours, as the paper limits them.</summary>
    public static readonly double[] FigureElevenColours = [0, 0.5, 1];

    /// <summary>Fig. 12's error targets ε.</summary>
    public static readonly double[] FigureTwelveTargets = [0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001];

    /// <summary>Fig. 12: QCoin's flips per step.</summary>
    public const int FigureTwelveFlips = 1000;

    public sealed record FitPoint(double OneQubit, int Steps, double Error);

    public sealed record Fit(DeviceNoiseModel Device, double PlateauTarget, IReadOnlyList<FitPoint> Scan, int BestSteps);

    public sealed record CurvePoint(string Series, int Steps, long Queries, double Error);

    public sealed record ImageRow(string Label, double TwoQubit, string Method, long Queries, double Error, double ExactShare);

    public sealed record TwelveRow(double Target, int QssQubits, long QssIterations, double QssError, int QCoinSteps, long QCoinIterations, double QCoinError);

    public sealed record Figures(Fit Fit, IReadOnlyList<CurvePoint> FigureTen, IReadOnlyList<ImageRow> FigureEleven, IReadOnlyList<TwelveRow> FigureTwelve);

    /// <summary>MC's mean absolute error at f = ½ with Q flips, for large Q: √(2/π) · ½ / √Q.</summary>
    public static double MonteCarloError(long queries) => Math.Sqrt(2 / Math.PI) * 0.5 / Math.Sqrt(queries);

    public static Figures Measure(NoiseEstimationSettings settings, Func<DeviceNoiseModel?, ICoinEngine> engine, SeededRandom inputs)
    {
        var fit = FitDevice(settings, engine);
        return new Figures(fit, FigureTen(settings, fit.Device, engine), FigureEleven(settings, fit.Device, engine), FigureTwelve(settings, engine, inputs));
    }

    private static double Error(IMeanEstimator estimator, IReadOnlyList<double[]> values, ICoinEngine engine)
    {
        using var _ = engine;
        var estimates = estimator.Estimate(values, engine);
        return values.Select((v, j) => Math.Abs(estimates[j] - CoinValues.Mean(v))).Average();
    }

    private static IMeanEstimator StepsEstimator(int k, long queries) => k == 0 ? new MonteCarloEstimator(queries) : new QCoinEstimator(queries, k);

    /// <summary>
    /// A fit of the device model to fig. 10. At f = ½ and k = 0 depolarizing noise leaves the coin unbiased, so the plateau is the
    /// readout's bias (P0 − P1)/2 alone: it is set to MC's error at <see cref="PaperPlateauQueries"/>, where the paper's curve stops
    /// falling, with P0 assumed. Then the one-qubit rate is scanned with that readout for the k with the lowest error at the
    /// largest budget, and the fit is the rate whose best k is the paper's (the middle of such rates, else the nearest).
    /// </summary>
    private static Fit FitDevice(NoiseEstimationSettings settings, Func<DeviceNoiseModel?, ICoinEngine> engine)
    {
        var plateau = MonteCarloError(PaperPlateauQueries);
        var readOneAsZero = AssumedReadZeroAsOne + 2 * plateau;
        var queries = NoiseEstimationSettings.StepBudgets[^1];
        var trials = Enumerable.Repeat(new[] { 0.5 }, Math.Max(100, settings.Trials / 4)).ToArray();
        var scan = new List<FitPoint>();
        foreach (var rate in FitOneQubitRates)
        {
            var device = new DeviceNoiseModel(rate, 0, AssumedReadZeroAsOne, readOneAsZero);
            for (var k = 0; k <= 7; k++) scan.Add(new FitPoint(rate, k, Error(StepsEstimator(k, queries), trials, engine(device))));
        }
        int Best(double rate) => scan.Where(p => p.OneQubit == rate).MinBy(p => p.Error)!.Steps;
        var matching = FitOneQubitRates.Where(r => Best(r) == NoiseEstimationReport.PaperStopSteps).ToArray();
        var chosen = matching.Length > 0 ? matching[matching.Length / 2] : FitOneQubitRates.MinBy(r => Math.Abs(Best(r) - NoiseEstimationReport.PaperStopSteps));
        return new Fit(new DeviceNoiseModel(chosen, 0, AssumedReadZeroAsOne, readOneAsZero), plateau, scan, Best(chosen));
    }

    private static List<CurvePoint> FigureTen(NoiseEstimationSettings settings, DeviceNoiseModel device, Func<DeviceNoiseModel?, ICoinEngine> engine)
    {
        var trials = Enumerable.Repeat(new[] { 0.5 }, settings.Trials).ToArray();
        var points = new List<CurvePoint>();
        foreach (var queries in NoiseEstimationSettings.StepBudgets)
        {
            points.Add(new CurvePoint("MC, noiseless", 0, queries, Error(new MonteCarloEstimator(queries), trials, engine(null))));
            for (var k = 0; k <= 7; k++)
                if (k == 0 || queries >= QCoinEstimator.MinimumQueries(k))
                    points.Add(new CurvePoint("device model", k, queries, Error(StepsEstimator(k, queries), trials, engine(device))));
        }
        return points;
    }

    private static List<ImageRow> FigureEleven(NoiseEstimationSettings settings, DeviceNoiseModel device, Func<DeviceNoiseModel?, ICoinEngine> engine)
    {
        // Pixels of the three colours in equal shares, each pixel's 8x8 subpixels its colour.
        var pixels = Enumerable.Range(0, settings.Trials).Select(j => Enumerable.Repeat(FigureElevenColours[j % FigureElevenColours.Length], 64).ToArray()).ToArray();
        var rows = new List<ImageRow>();
        void Add(string label, DeviceNoiseModel? model, IMeanEstimator estimator, double twoQubit)
        {
            using var e = engine(model);
            var estimates = estimator.Estimate(pixels, e);
            var errors = pixels.Select((v, j) => Math.Abs(estimates[j] - v[0])).ToArray();
            rows.Add(new ImageRow(label, twoQubit, estimator.Name, estimator.Queries, errors.Average(), errors.Count(x => x < 0.5 / 255) / (double)errors.Length));
        }
        var qss = new QssEstimator(2);
        Add("noiseless", null, qss, 0);
        Add("readout only", new DeviceNoiseModel(0, 0, device.ReadZeroAsOne, device.ReadOneAsZero), qss, 0);
        foreach (var p2 in FigureElevenTwoQubitRates)
            Add("device model", new DeviceNoiseModel(device.OneQubit, p2, device.ReadZeroAsOne, device.ReadOneAsZero), qss, p2);
        var qcoin = new QCoinEstimator(SupersampleSettings.DefaultQueries, 3);
        Add("noiseless", null, qcoin, 0);
        Add("device model", device, qcoin, 0);
        return rows;
    }

    private static List<TwelveRow> FigureTwelve(NoiseEstimationSettings settings, Func<DeviceNoiseModel?, ICoinEngine> engine, SeededRandom inputs)
    {
        // QSS: its exact mean absolute error over uniform means (midpoint rule, 2000 means) for each t; QCoin: its measured error
        // over uniform random means with L flips per step for each k.
        var qssError = Enumerable.Range(1, 12).Select(ExactQssError).ToArray();
        var means = Enumerable.Range(0, Math.Max(100, settings.Trials / 4)).Select(_ => new[] { inputs.NextDouble() }).ToArray();
        var qcoinError = Enumerable.Range(1, 10).Select(k =>
        {
            var queries = FigureTwelveFlips * QCoinEstimator.MinimumQueries(k);
            return Error(new QCoinEstimator(queries, k), means, engine(null));
        }).ToArray();
        return FigureTwelveTargets.Select(target =>
        {
            var t = Array.FindIndex(qssError, e => e <= target) + 1;
            var k = Array.FindIndex(qcoinError, e => e <= target) + 1;
            return new TwelveRow(target, t, t > 0 ? (1L << t) - 1 : 0, t > 0 ? qssError[t - 1] : double.NaN,
                k, k > 0 ? 1L << (k - 1) : 0, k > 0 ? qcoinError[k - 1] : double.NaN);
        }).ToList();
    }

    /// <summary>QSS's mean absolute error (estimate sin²(πy/2^t)) averaged over means uniform on [0, 1], from its exact readout distribution.</summary>
    public static double ExactQssError(int counterBits)
    {
        const int cells = 2000;
        var total = 0.0;
        for (var c = 0; c < cells; c++)
        {
            var f = (c + 0.5) / cells;
            var readout = CoinProbability.QssReadout(f, counterBits);
            for (var y = 0; y < readout.Length; y++)
            {
                var s = Math.Sin(Math.PI * y / readout.Length);
                total += readout[y] * Math.Abs(s * s - f);
            }
        }
        return total / cells;
    }
}
