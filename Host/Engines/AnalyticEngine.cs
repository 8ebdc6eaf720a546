using QuantumRayTracing.Noise;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Engines;

/// <summary>
/// Samples each request's exact outcome distribution instead of simulating it: a marked index with
/// probability sin²((2r+1)θ), uniform among the marked; otherwise uniform among the unmarked.
/// Deterministic for a given random stream and request order. Under noise, each run is ideal with its
/// fidelity Φ and otherwise reads a uniform index of the register (<see cref="DepolarizingApproximation"/>).
/// </summary>
public sealed class AnalyticEngine(SeededRandom random, NoiseModel? noise = null, DepolarizingApproximation? approximation = null) : IGroverEngine
{
    public string Name => "analytic";

    /// <summary>The noise the runs are sampled under; the ideal model takes the exact path, draw for draw.</summary>
    public NoiseModel Noise { get; } = noise is { QubitLoss: > 0 }
        ? throw new ArgumentException("the analytic engine does not model qubit loss", nameof(noise))
        : noise ?? NoiseModel.None;

    public DepolarizingApproximation Approximation { get; } = approximation ?? DepolarizingApproximation.Default;

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
        if (!Noise.IsNoiseless && random.NextDouble() >= Approximation.RunFidelity(Noise, request))
            return random.NextInt(1 << SearchRegisters.For(set.Count).IndexQubits);
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
