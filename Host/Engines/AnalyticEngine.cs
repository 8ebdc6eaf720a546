using QuantumRayTracing.Randomness;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Engines;

/// <summary>
/// Samples each request's exact outcome distribution instead of simulating it: a marked index with
/// probability sin²((2r+1)θ), uniform among the marked; otherwise uniform among the unmarked.
/// Deterministic for a given random stream and request order.
/// </summary>
public sealed class AnalyticEngine(SeededRandom random) : IGroverEngine
{
    public string Name => "analytic";

    public IReadOnlyList<int> Measure(IReadOnlyList<GroverRequest> requests)
    {
        var measured = new int[requests.Count];
        for (var k = 0; k < requests.Count; k++)
            measured[k] = Sample(requests[k]);
        return measured;
    }

    private int Sample(GroverRequest request)
    {
        var set = request.Marked;
        var hitsMarked = random.NextDouble() < GroverProbability.OfMarked(request);
        if (hitsMarked)
            return set.Indices[random.NextInt(set.MarkedCount)];
        // The k-th unmarked index: step past every marked index at or below the candidate.
        var index = random.NextInt(set.Count - set.MarkedCount);
        foreach (var m in set.Indices)
        {
            if (m > index) break;
            index++;
        }
        return index;
    }

    public void Dispose() { }
}
