using QuantumRayTracing.Engines;

namespace QuantumRayTracing.Search;

/// <summary>
/// The probability that a search reports nothing although t &gt; 0 primitives are accepted, for the
/// termination criterion of the paper's sec. 6.2. For QSearch three ways: eq. 10 as printed
/// (cos²((M_l+1)θ) per bound), eq. 10 evaluated at r = M_l (cos²((2M_l+1)θ), which reproduces the
/// paper's table 6 closely wherever our round-rule M set is the paper's: not at N = 32), and the exact rate of our QSearch (the initial sample, then r_l uniform on 1..M_l
/// per bound). For the randomized classical search, eq. 11. Each averages over a distribution p_t of t
/// (the paper's is uniform on 1..N).
/// </summary>
public static class FalseNegativeRate
{
    /// <summary>P(marked) of one Grover run over <paramref name="count"/> rows, <paramref name="marked"/> marked, after <paramref name="iterations"/> iterations.</summary>
    public delegate double RunSuccess(int count, int marked, int iterations);

    /// <summary>Eq. 10 as printed: ∏_l Σ_t p_t cos²((M_l + 1)θ_t).</summary>
    public static double Eq10AsPrinted(QSearchSchedule schedule, IReadOnlyList<double> pt) =>
        schedule.Bounds.Aggregate(1.0, (product, m) => product * Average(pt, t => Square(Math.Cos((m + 1) * Theta(t, schedule.Count)))));

    /// <summary>Eq. 10 at r = M_l: ∏_l Σ_t p_t cos²((2M_l + 1)θ_t).</summary>
    public static double Eq10AtBound(QSearchSchedule schedule, IReadOnlyList<double> pt) =>
        schedule.Bounds.Aggregate(1.0, (product, m) => product * Average(pt, t => Square(Math.Cos((2 * m + 1) * Theta(t, schedule.Count)))));

    /// <summary>
    /// The exact miss probability of <see cref="QSearch"/>: Σ_t p_t · (1 − t/N) · ∏_l (1 − mean over
    /// r = 1..M_l of sin²((2r + 1)θ_t)).
    /// </summary>
    /// <remarks>
    /// <paramref name="success"/> replaces each run's ideal P(marked), sin²((2r + 1)θ), with another (a noisy machine's);
    /// null keeps the ideal one.
    /// </remarks>
    public static double QSearchExact(QSearchSchedule schedule, IReadOnlyList<double> pt, RunSuccess? success = null) =>
        Average(pt, t => QSearchExact(schedule, t, success));

    /// <summary>The exact miss probability of <see cref="QSearch"/> for one t, with the runs' success by <paramref name="success"/> (null: ideal).</summary>
    public static double QSearchExact(QSearchSchedule schedule, int t, RunSuccess? success = null)
    {
        var n = schedule.Count;
        RunSuccess ofMarked = success ?? GroverProbability.OfMarked;
        // A run misses with 1 − P(marked) of Grover's closed form; a fixed list runs each r once, Algorithm 1
        // takes the initial sample (r = 0) and then r uniform on 1..M_l per bound.
        if (schedule.IsFixed)
            return schedule.Bounds.Aggregate(1.0, (miss, r) => miss * (1 - ofMarked(n, t, r)));
        var miss = 1 - ofMarked(n, t, 0);
        foreach (var m in schedule.Bounds)
        {
            var found = 0.0;
            for (var r = 1; r <= m; r++) found += ofMarked(n, t, r);
            miss *= 1 - found / m;
        }
        return Math.Max(0, miss);
    }

    /// <summary>Eq. 11, exact: Σ_t p_t ∏_{j &lt; k} (N − t − j) / (N − j), k primitives drawn without replacement.</summary>
    public static double Randomized(int count, int tested, IReadOnlyList<double> pt) =>
        Average(pt, t =>
        {
            var miss = 1.0;
            for (var j = 0; j < tested; j++) miss *= Math.Max(0, (double)(count - t - j) / (count - j));
            return miss;
        });

    /// <summary>The paper's p_t: t uniform on 1..<paramref name="last"/> (index t of the result; index 0 is t = 0, weight 0).</summary>
    public static double[] Uniform(int count, int last)
    {
        var pt = new double[count + 1];
        for (var t = 1; t <= last; t++) pt[t] = 1.0 / last;
        return pt;
    }

    private static double Theta(int t, int n) => Math.Asin(Math.Sqrt((double)t / n));

    private static double Square(double x) => x * x;

    // Σ_t p_t f(t) over t ≥ 1, pt indexed by t.
    private static double Average(IReadOnlyList<double> pt, Func<int, double> f)
    {
        var sum = 0.0;
        for (var t = 1; t < pt.Count; t++)
            if (pt[t] > 0) sum += pt[t] * f(t);
        return sum;
    }
}
