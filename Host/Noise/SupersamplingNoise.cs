using QuantumRayTracing.Engines;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Noise;

/// <summary>
/// The global depolarizing approximation (<see cref="DepolarizingApproximation"/>) of the supersampling circuits:
/// with probability Φ a run is the ideal one, otherwise its qubits are left maximally mixed. A coin flip after m
/// Grover operators then shows a head with probability Φ · sin²((2m+1)θ) + (1 − Φ) · u, and a QSS readout is the
/// ideal distribution mixed towards uniform over the 2^t counter values by its Φ.
/// </summary>
/// <remarks>
/// Φ = (1 − p)^(s · L) over the run's noise locations L (<see cref="CoinNoiseLocations"/>): Φ = F₀ · F^m, F per Grover
/// operator and F₀ for the preparation and measurement, which count by their own locations (as the Grover engine's
/// model does), not as a half operator. For the mean coin F₀ is close to F^(1/2) anyway: an operator is two
/// preparations and a reflection. u is what a maximally mixed register reads as a head: ½ for the mean and direct coins
/// (the coin qubit alone decides), 1/2^(n+1) for the shifted coin, whose head also needs the n subpixel qubits at 0.
/// The direct coin's model is exact, not an approximation: on one qubit a Pauli error of total probability p (p/3 each)
/// is the depolarizing channel ρ → (1 − 4p/3) ρ + (4p/3) I/2, which commutes with every gate, so Φ = (1 − 4p/3)^L and
/// the harmful share plays no part. Asymmetric Pauli noise is taken by its total rate p = px + py + pz throughout.
/// </remarks>
public static class SupersamplingNoise
{
    /// <summary>The noise model as supersampling results name it: on the analytic engine this approximation, elsewhere the simulator's noise.</summary>
    public static string Description(EngineKind kind, NoiseModel noise)
    {
        ArgumentNullException.ThrowIfNull(noise);
        return noise.IsNoiseless || !kind.ApproximatesNoise ? noise.Description()
            : $"{noise.Description()}, global depolarizing approximation over the supersampling circuits' counted locations, harmful share {DepolarizingApproximation.DefaultHarmfulShare:0.###} (the one-qubit coin exact)";
    }

    /// <summary>F per Grover operator of a coin: the probability that one operator is left unharmed.</summary>
    public static double GroverOperatorFidelity(CoinKind kind, IReadOnlyList<double> amplitudes, NoiseModel noise, DepolarizingApproximation? approximation = null) =>
        Fidelity(kind, CoinNoiseLocations.GroverOperator(kind, amplitudes), noise, approximation);

    /// <summary>Φ of one flip amplified by <paramref name="iterations"/> operators: F₀ · F^m.</summary>
    public static double CoinFidelity(CoinKind kind, IReadOnlyList<double> amplitudes, int iterations, NoiseModel noise, DepolarizingApproximation? approximation = null) =>
        Fidelity(kind, CoinNoiseLocations.Flip(kind, amplitudes, iterations), noise, approximation);

    /// <summary>The weight of the ideal state after a single qubit's <paramref name="locations"/> depolarizing channels: (1 − 4p/3)^L, exact.</summary>
    public static double SingleQubitFidelity(NoiseModel noise, long locations) =>
        noise.PerGate <= 0 ? 1.0 : Math.Pow(1 - 4 * noise.PerGate / 3, locations);

    private static double Fidelity(CoinKind kind, long locations, NoiseModel noise, DepolarizingApproximation? approximation) =>
        kind == CoinKind.Direct ? SingleQubitFidelity(noise, locations) : (approximation ?? DepolarizingApproximation.Default).Fidelity(noise, locations);

    /// <summary>u: the head probability of a flip whose qubits are maximally mixed.</summary>
    public static double UniformHeadShare(CoinKind kind, int subpixels) =>
        kind == CoinKind.Shifted ? 1.0 / (2L << CoinRegisters.SubpixelQubits(subpixels)) : 0.5;

    /// <summary>The head probability of a flip under <paramref name="noise"/>: Φ · sin²((2m+1)θ) + (1 − Φ) · u; the ideal one without noise.</summary>
    public static double CoinHeadProbability(CoinKind kind, IReadOnlyList<double> amplitudes, int iterations, NoiseModel noise, DepolarizingApproximation? approximation = null)
    {
        var ideal = CoinProbability.Head(CoinProbability.HeadAmplitude(kind, amplitudes), iterations);
        if (noise.IsNoiseless) return ideal;
        var fidelity = CoinFidelity(kind, amplitudes, iterations, noise, approximation);
        // Past p = 3/4 the single-qubit weight can turn negative (over-depolarized); the mixture stays a probability.
        return Math.Clamp(fidelity * ideal + (1 - fidelity) * UniformHeadShare(kind, amplitudes.Count), 0, 1);
    }

    /// <summary>Φ of one QSS run with <paramref name="counterBits"/> counter qubits.</summary>
    public static double QssFidelity(IReadOnlyList<double> amplitudes, int counterBits, NoiseModel noise, DepolarizingApproximation? approximation = null) =>
        (approximation ?? DepolarizingApproximation.Default).Fidelity(noise, CoinNoiseLocations.Qss(amplitudes, counterBits));

    /// <summary>The QSS readout distribution under <paramref name="noise"/>: Φ · ideal + (1 − Φ) / 2^t; the ideal one without noise.</summary>
    public static double[] QssReadout(IReadOnlyList<double> amplitudes, int counterBits, NoiseModel noise, DepolarizingApproximation? approximation = null)
    {
        var amplitude = CoinProbability.HeadAmplitude(CoinKind.Mean, amplitudes);
        var ideal = CoinProbability.QssReadout(amplitude * amplitude, counterBits);
        if (noise.IsNoiseless) return ideal;
        var fidelity = QssFidelity(amplitudes, counterBits, noise, approximation);
        return ideal.Select(q => fidelity * q + (1 - fidelity) / ideal.Length).ToArray();
    }
}
