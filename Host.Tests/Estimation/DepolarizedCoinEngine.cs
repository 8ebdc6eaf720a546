using QuantumRayTracing.Noise;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Tests.Estimation;

/// <summary>
/// Noisy coins for the estimator tests: the analytic engine's single-qubit direct coin under depolarizing noise, whose
/// model is exact (Φ = (1 − 4p/3)^L over L noise locations: 2 for a flip's preparation and measurement, 4 per Grover
/// operator). So a flip after m operators is a head with probability Φ · sin²((2m+1)θ) + (1 − Φ) / 2 with
/// Φ = e^(−γ(m+½)) exactly, for the per-gate error p that gives F = (1 − 4p/3)^4 = e^(−γ).
/// </summary>
internal static class DepolarizedCoinEngine
{
    public static ICoinEngine Create(SeededRandom random, double decay)
    {
        var noise = decay == 0 ? null : NoiseModel.Depolarizing(0.75 * (1 - Math.Exp(-decay / 4)));
        return new DirectCoinEngine(new AnalyticCoinEngine(random, noise));
    }
}
