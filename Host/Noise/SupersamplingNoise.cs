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
/// </remarks>
public static class SupersamplingNoise
{
    /// <summary>F per Grover operator of a coin: the probability that one operator is left unharmed.</summary>
    public static double GroverOperatorFidelity(CoinKind kind, IReadOnlyList<double> amplitudes, NoiseModel noise, DepolarizingApproximation? approximation = null) =>
        (approximation ?? DepolarizingApproximation.Default).Fidelity(noise, CoinNoiseLocations.GroverOperator(kind, amplitudes));

    /// <summary>Φ of one flip amplified by <paramref name="iterations"/> operators: F₀ · F^m.</summary>
    public static double CoinFidelity(CoinKind kind, IReadOnlyList<double> amplitudes, int iterations, NoiseModel noise, DepolarizingApproximation? approximation = null) =>
        (approximation ?? DepolarizingApproximation.Default).Fidelity(noise, CoinNoiseLocations.Flip(kind, amplitudes, iterations));

    /// <summary>u: the head probability of a flip whose qubits are maximally mixed.</summary>
    public static double UniformHeadShare(CoinKind kind, int subpixels) =>
        kind == CoinKind.Shifted ? 1.0 / (2L << CoinRegisters.SubpixelQubits(subpixels)) : 0.5;

    /// <summary>The head probability of a flip under <paramref name="noise"/>: Φ · sin²((2m+1)θ) + (1 − Φ) · u; the ideal one without noise.</summary>
    public static double CoinHeadProbability(CoinKind kind, IReadOnlyList<double> amplitudes, int iterations, NoiseModel noise, DepolarizingApproximation? approximation = null)
    {
        var ideal = CoinProbability.Head(CoinProbability.HeadAmplitude(kind, amplitudes), iterations);
        if (noise.IsNoiseless) return ideal;
        var fidelity = CoinFidelity(kind, amplitudes, iterations, noise, approximation);
        return fidelity * ideal + (1 - fidelity) * UniformHeadShare(kind, amplitudes.Count);
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
