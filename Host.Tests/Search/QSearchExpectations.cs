using QuantumRayTracing.Search;

namespace QuantumRayTracing.Tests.Search;

/// <summary>QSearch's exact false-negative probability, computed from its definition for a given schedule.</summary>
public static class QSearchExpectations
{
    /// <summary>
    /// P(not found | t ≥ 1) = (1 − t/N) · Π_l [1 − (1/M_l) Σ_{r=1..M_l} sin²((2r+1)θ)]: the initial
    /// sample misses, then every bounded run misses with r uniform in 1..M_l.
    /// </summary>
    public static double FalseNegative(int count, int marked, QSearchSchedule schedule)
    {
        var theta = Math.Asin(Math.Sqrt((double)marked / count));
        var miss = 1 - (double)marked / count;
        foreach (var m in schedule.Bounds)
        {
            var success = Enumerable.Range(1, m).Average(r => Math.Pow(Math.Sin((2 * r + 1) * theta), 2));
            miss *= 1 - success;
        }
        return miss;
    }
}
