using QuantumRayTracing.Search;

namespace QuantumRayTracing.Engines;

/// <summary>Grover's closed form: after r iterations with t of N marked, P(marked) = sin²((2r+1)θ), sin²θ = t/N.</summary>
public static class GroverProbability
{
    public static double OfMarked(int count, int marked, int iterations)
    {
        if (marked == 0) return 0.0;
        if (marked == count) return 1.0;
        var theta = Math.Asin(Math.Sqrt((double)marked / count));
        var s = Math.Sin((2 * iterations + 1) * theta);
        return s * s;
    }

    /// <summary>
    /// The iteration count that maximises <see cref="OfMarked(int, int, int)"/>: the r nearest
    /// π/(4θ) − 1/2, that is floor(π/(4θ)). None marked or all marked: 0, as no r helps.
    /// </summary>
    public static int OptimalIterations(int count, int marked)
    {
        if (marked == 0 || marked == count) return 0;
        var theta = Math.Asin(Math.Sqrt((double)marked / count));
        return (int)Math.Floor(Math.PI / (4 * theta));
    }

    public static double OfMarked(GroverRequest request) =>
        OfMarked(request.Marked.Count, request.Marked.MarkedCount, request.Iterations);
}
