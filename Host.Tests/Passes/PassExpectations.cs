using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Search;

namespace QuantumRayTracing.Tests.Passes;

/// <summary>Exact probabilities of TracePass outcomes on the analytic engine, from QSearch's false-negative rate.</summary>
public static class PassExpectations
{
    /// <summary>
    /// P(a ray with <paramref name="accepted"/> hits in its full range does not end on the closest one)
    /// after <paramref name="rounds"/> strict-order rounds. The state is m, the number of accepted rows
    /// better than the current hit (all of them before the first find). A round with m ≥ 1 marked rows
    /// misses with QSearch's false-negative probability, otherwise lands uniformly on one of the m rows
    /// (the engine is uniform among marked indices), leaving 0..m − 1 better ones; m = 0 is final.
    /// </summary>
    public static double WrongAfter(int count, int accepted, int rounds, QSearchSchedule schedule)
    {
        var state = new double[accepted + 1];
        state[accepted] = 1;
        for (var round = 0; round < rounds; round++)
        {
            var next = new double[accepted + 1];
            next[0] = state[0];
            for (var m = 1; m <= accepted; m++)
            {
                if (state[m] == 0) continue;
                var miss = QSearchExpectations.FalseNegative(count, m, schedule);
                next[m] += state[m] * miss;
                for (var j = 0; j < m; j++) next[j] += state[m] * (1 - miss) / m;
            }
            state = next;
        }
        return 1 - state[0];
    }

    /// <summary>
    /// The smallest interval of the number of successes among independent trials with the given
    /// probabilities (a Poisson-binomial count) whose two tails outside it each hold at most α/2.
    /// </summary>
    public static (int Low, int High) PoissonBinomialInterval(IReadOnlyList<double> probabilities, double alpha)
    {
        var distribution = new double[probabilities.Count + 1];
        distribution[0] = 1;
        for (var i = 0; i < probabilities.Count; i++)
        {
            var p = probabilities[i];
            for (var k = i + 1; k >= 1; k--) distribution[k] = distribution[k] * (1 - p) + distribution[k - 1] * p;
            distribution[0] *= 1 - p;
        }
        var low = 0;
        for (var below = distribution[0]; low < probabilities.Count && below <= alpha / 2; below += distribution[++low]) { }
        var high = probabilities.Count;
        for (var above = distribution[high]; high > 0 && above <= alpha / 2; above += distribution[--high]) { }
        return (low, high);
    }
}
