using QuantumRayTracing.Randomness;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// Error against queries over uniform random means (paper 003, figs. 7-8) on the analytic engine (the exact
/// outcome distributions; tests show the fullstate engine agrees in distribution), and the QSS lookup table's
/// accuracy with hit counts equally likely (thesis 004).
/// </summary>
public static class SupersamplingBenchmark
{
    public static readonly int[] QueryLevels = [60, 120, 240, 480, 960, 1600, 3200];

    /// <summary>One point: method, its parameter, queries spent, mean absolute error over the trials.</summary>
    public sealed record Point(string Method, int Parameter, long Queries, double MeanError);

    public static List<Point> ErrorVersusQueries(int trials, ulong seed)
    {
        var root = new SeededRandom(seed);
        var means = root.Fork(RandomStreams.Scenario);
        var values = Enumerable.Range(0, trials).Select(_ => new[] { means.NextDouble() }).ToArray();
        var points = new List<Point>();
        var stream = 0UL;
        Point Run(IMeanEstimator estimator, string method, int parameter)
        {
            var engine = new AnalyticCoinEngine(root.Fork(RandomStreams.Supersampling + stream++));
            var estimates = estimator.Estimate(values, engine);
            var error = estimates.Select((e, j) => Math.Abs(e - values[j][0])).Average();
            var point = new Point(method, parameter, estimator.Queries, error);
            points.Add(point);
            return point;
        }
        foreach (var q in QueryLevels)
        {
            Run(new MonteCarloEstimator(q), "mc", 0);
            for (var k = 1; k <= 7; k++)
                if (q >= QCoinEstimator.MinimumQueries(k)) Run(new QCoinEstimator(q, k), "qcoin", k);
            for (var levels = 0; levels <= 14; levels++)
                if (q >= MlaeSchedule.Default.QueriesPerShot(levels)) Run(new MaximumLikelihoodEstimator(q, levels), "mlae", levels);
            for (var levels = 0; levels <= 10; levels++)
                if (q >= MlaeSchedule.Doubling.QueriesPerShot(levels)) Run(new MaximumLikelihoodEstimator(q, levels, MlaeSchedule.Doubling), "mlae-doubling", levels);
        }
        for (var t = 4; t <= 11; t++) Run(new QssEstimator(t), "qss", t);
        return points;
    }

    /// <summary>For each query level the point of <paramref name="method"/> with the lowest error.</summary>
    public static List<Point> Best(IEnumerable<Point> points, string method) =>
        points.Where(p => p.Method == method).GroupBy(p => p.Queries).Select(g => g.MinBy(p => p.MeanError)!).OrderBy(p => p.Queries).ToList();

    /// <summary>Least-squares slope of log10(error) on log10(queries) over the points with queries in [from, to].</summary>
    public static double Slope(IEnumerable<Point> points, long from, long to) =>
        LogLogFit.Slope(points.Where(p => p.Queries >= from && p.Queries <= to).Select(p => ((double)p.Queries, p.MeanError)));

    /// <summary>Mean error in hits and share of exact readouts of a lookup table, hit counts 0..N equally likely.</summary>
    public static (double MeanError, double ExactShare) TableAccuracy(QssLookupTable table)
    {
        var (error, exact) = (0.0, 0.0);
        var columns = table.Subpixels + 1;
        for (var h = 0; h < columns; h++)
            for (var y = 0; y < table.Readouts; y++)
            {
                error += table.Probabilities[y, h] * Math.Abs(table.HitsOfReadout[y] - h) / columns;
                if (table.HitsOfReadout[y] == h) exact += table.Probabilities[y, h] / columns;
            }
        return (error, exact);
    }

    /// <summary>Monte Carlo's mean error in hits and exact share with <paramref name="samples"/> subpixel samples (with replacement), hit counts equally likely; exact sums.</summary>
    public static (double MeanError, double ExactShare) MonteCarloHitAccuracy(int subpixels, int samples)
    {
        var (error, exact) = (0.0, 0.0);
        for (var h = 0; h <= subpixels; h++)
        {
            var p = (double)h / subpixels;
            for (var x = 0; x <= samples; x++)
            {
                var probability = BinomialProbability(samples, x, p);
                var estimate = Math.Round((double)x * subpixels / samples, MidpointRounding.AwayFromZero);
                error += probability * Math.Abs(estimate - h) / (subpixels + 1);
                if (estimate == h) exact += probability / (subpixels + 1);
            }
        }
        return (error, exact);
    }

    private static double BinomialProbability(int n, int x, double p)
    {
        if (p <= 0) return x == 0 ? 1 : 0;
        if (p >= 1) return x == n ? 1 : 0;
        var log = 0.0;
        for (var i = 1; i <= x; i++) log += Math.Log((double)(n - x + i) / i);
        return Math.Exp(log + x * Math.Log(p) + (n - x) * Math.Log(1 - p));
    }
}
