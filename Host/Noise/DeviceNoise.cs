using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Noise;

/// <summary>
/// The outcome distributions of the QCoin paper's device circuits under a <see cref="DeviceNoiseModel"/>: the gates'
/// noise as a global depolarizing weight Φ on the ideal distribution (the rest uniform), then each measured bit
/// flipped by the readout error, which is exact.
/// </summary>
/// <remarks>
/// The single-qubit coin is exact: one qubit's depolarizing channel at rate p is ρ → (1 − 4p/3) ρ + (4p/3) I/2 and
/// commutes with every gate, so Φ = (1 − 4p₁/3)^L₁. The QSS run spans t + 1 qubits, where Φ is the approximation
/// (1 − p₁)^(s·L₁) · (1 − p₂)^(s·2·L₂) over its L₁ one-qubit and L₂ two-qubit gates (<see cref="DeviceCircuitGates"/>;
/// a two-qubit gate is noise on both its qubits) with the harmful share s of <see cref="DepolarizingApproximation"/>.
/// </remarks>
public static class DeviceNoise
{
    /// <summary>Φ of one flip of the single-qubit coin after m Grover operators.</summary>
    public static double DirectCoinFidelity(DeviceNoiseModel device, int iterations) =>
        Math.Pow(1 - 4 * device.OneQubit / 3, DeviceCircuitGates.DirectCoin(iterations).OneQubit);

    /// <summary>The probability of reading a head from the single-qubit coin of head amplitude √f after m operators.</summary>
    public static double DirectCoinHeadProbability(DeviceNoiseModel device, double headAmplitude, int iterations)
    {
        var fidelity = DirectCoinFidelity(device, iterations);
        var head = Math.Clamp(fidelity * CoinProbability.Head(headAmplitude, iterations) + (1 - fidelity) / 2, 0, 1);
        return device.ReadOne(head);
    }

    /// <summary>Φ of one QSS run on the single-qubit coin with t counter qubits.</summary>
    public static double DirectQssFidelity(DeviceNoiseModel device, int counterBits, DepolarizingApproximation? approximation = null)
    {
        var (one, two) = DeviceCircuitGates.DirectQss(counterBits);
        var model = approximation ?? DepolarizingApproximation.Default;
        return model.Fidelity(NoiseModel.Depolarizing(device.OneQubit), one) * model.Fidelity(NoiseModel.Depolarizing(device.TwoQubit), 2 * two);
    }

    /// <summary>The readout distribution of QSS on the single-qubit coin of head amplitude √f: Φ · ideal + (1 − Φ)/2^t, then the readout flips.</summary>
    public static double[] DirectQssReadout(DeviceNoiseModel device, double headAmplitude, int counterBits, DepolarizingApproximation? approximation = null)
    {
        var ideal = CoinProbability.QssReadout(headAmplitude * headAmplitude, counterBits);
        var fidelity = DirectQssFidelity(device, counterBits, approximation);
        return ReadBits(device, ideal.Select(q => fidelity * q + (1 - fidelity) / ideal.Length).ToArray(), counterBits);
    }

    /// <summary>A distribution over t-bit values after each bit is flipped independently by the readout error.</summary>
    public static double[] ReadBits(DeviceNoiseModel device, double[] distribution, int bits)
    {
        if (!device.HasReadoutError) return distribution;
        var read = new double[distribution.Length];
        for (var y = 0; y < distribution.Length; y++)
        {
            for (var seen = 0; seen < distribution.Length; seen++)
            {
                var p = distribution[y];
                for (var b = 0; b < bits; b++)
                {
                    var (truth, shown) = ((y >> b) & 1, (seen >> b) & 1);
                    var flip = truth == 0 ? device.ReadZeroAsOne : device.ReadOneAsZero;
                    p *= truth == shown ? 1 - flip : flip;
                }
                read[seen] += p;
            }
        }
        return read;
    }
}
