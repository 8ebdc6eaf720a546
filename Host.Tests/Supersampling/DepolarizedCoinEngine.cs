using QuantumRayTracing.Randomness;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Tests.Supersampling;

/// <summary>
/// Synthetic noisy coins for the estimator tests: a flip after m Grover operators is a head with probability
/// Φ · sin²((2m+1)θ) + (1 − Φ) / 2 with Φ = e^(−γ(m+½)), the globally depolarized coin, drawn from a seeded generator.
/// </summary>
internal sealed class DepolarizedCoinEngine(SeededRandom random, double decay) : ISupersamplingEngine
{
    public string Name => $"depolarized coin, decay {decay} per Grover operator";

    public IReadOnlyList<int> FlipCoins(IReadOnlyList<CoinRequest> requests) => requests.Select(request =>
    {
        var theta = Math.Asin(CoinProbability.HeadAmplitude(request.Kind, request.Amplitudes));
        var p = NoiseAwareMaximumLikelihoodEstimator.HeadProbability(theta, decay, request.Iterations);
        var heads = 0;
        for (var flip = 0; flip < request.Flips; flip++)
            if (random.NextDouble() < p) heads++;
        return heads;
    }).ToArray();

    public IReadOnlyList<int[]> ReadCounters(IReadOnlyList<QssRequest> requests) => throw new NotSupportedException("coins only");

    public void Dispose() { }
}
