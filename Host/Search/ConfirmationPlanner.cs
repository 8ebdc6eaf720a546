using QuantumRayTracing.Engines;

namespace QuantumRayTracing.Search;

/// <summary>
/// Chooses a fixed list of Grover iteration counts for confirming searches: where a ray most likely has
/// nothing left to find, what matters is the cost of a search that finds nothing (its t = 0 cost), held
/// to a miss probability for the t the scene actually has. The cheapest list of up to
/// <see cref="MaxRuns"/> runs, each r in 1..ceil(sqrt N), whose exact miss probability is at most the
/// bound for every t in 1..maxT, costed in the conservative count (Σ (r + 1) queries plus one classical
/// test per run).
/// </summary>
public static class ConfirmationPlanner
{
    /// <summary>The t a confirmation is planned for: at most ~6 primitives lie on a Qornell ray, 9 in Depth Complexity's deepest quadrant.</summary>
    public const int MaxT = 8;

    /// <summary>The schedule's largest exact miss probability over t = 1..<see cref="MaxT"/>.</summary>
    /// <remarks>With <paramref name="machine"/>, the machine's misses (<see cref="IHitSearch.MachineMissProbability"/>) rather than the plan's.</remarks>
    public static double WorstMiss(IHitSearch search, int count, QSearchSchedule? schedule, bool machine = false)
    {
        var worst = 0.0;
        for (var t = 1; t <= Math.Min(count, MaxT); t++)
        {
            var pt = new double[t + 1];
            pt[t] = 1;
            worst = Math.Max(worst, machine ? search.MachineMissProbability(count, pt, schedule) : search.MissProbability(count, pt, paperFormula: false, schedule));
        }
        return worst;
    }

    public const int MaxRuns = 4;

    /// <summary>The cheapest list, smallest r first; null when no list of <see cref="MaxRuns"/> runs meets the bound.</summary>
    public static QSearchSchedule? Cheapest(int count, int maxT, double maxMiss)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(maxT, 1);
        maxT = Math.Min(maxT, count);
        var cap = QSearchSchedule.CeilSqrt(count);
        // miss[r][t]: the chance one run with r iterations measures an unmarked index, cos²((2r + 1)θ_t).
        var miss = new double[cap + 1][];
        for (var r = 1; r <= cap; r++)
        {
            miss[r] = new double[maxT + 1];
            for (var t = 1; t <= maxT; t++) miss[r][t] = 1 - GroverProbability.OfMarked(count, t, r);
        }
        int[]? best = null;
        var bestCost = int.MaxValue;
        var bestWorst = double.MaxValue;
        var list = new List<int>();
        var product = new double[maxT + 1];
        void Extend(int from, double[] current)
        {
            if (list.Count > 0)
            {
                var cost = list.Sum(r => r + 2);
                var worst = current.Skip(1).Max();
                if (worst <= maxMiss && (cost < bestCost || (cost == bestCost && worst < bestWorst)))
                    (best, bestCost, bestWorst) = ([.. list], cost, worst);
            }
            if (list.Count == MaxRuns) return;
            for (var r = from; r <= cap; r++)
            {
                if (list.Sum(x => x + 2) + r + 2 > bestCost) break;
                var next = new double[maxT + 1];
                for (var t = 1; t <= maxT; t++) next[t] = current[t] * miss[r][t];
                list.Add(r);
                Extend(r, next);
                list.RemoveAt(list.Count - 1);
            }
        }
        Array.Fill(product, 1.0);
        Extend(1, product);
        return best is null ? null : QSearchSchedule.Fixed(count, best);
    }
}
