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

    public static double OfMarked(GroverRequest request) =>
        OfMarked(request.Marked.Count, request.Marked.MarkedCount, request.Iterations);
}
