namespace QuantumRayTracing.Noise;

/// <summary>
/// One- and two-qubit gates of the QCoin paper's device circuits as the Q# operations apply them, in closed form
/// (tested against the circuits the QDK extracts): the single-qubit coin (<c>CountDirectCoinHeadsOnDevice</c>) and
/// QSS on it (<c>MeasureDirectQssOnDevice</c>). Measurements are not gates here: the device model reads them clean
/// and flips the bits by its readout error.
/// </summary>
public static class DeviceCircuitGates
{
    /// <summary>One flip after m Grover operators: one Ry, then Z, Ry, Z, Ry per operator; no two-qubit gate.</summary>
    public static (long OneQubit, long TwoQubit) DirectCoin(int iterations) => (1 + 4L * iterations, 0);

    /// <summary>
    /// One QSS run with t counter qubits: H on the counter and one Ry on the coin; 2^t − 1 controlled operators, each two
    /// CZ and two controlled Ry (two Ry and two CNOT each); the inverse QFT's t H and t(t − 1)/2 controlled phases (three Rz
    /// and two CNOT each); ⌊t/2⌋ SWAPs of three CNOTs.
    /// </summary>
    public static (long OneQubit, long TwoQubit) DirectQss(int counterBits)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(counterBits, 1);
        var t = (long)counterBits;
        var operators = (1L << counterBits) - 1;
        var phases = t * (t - 1) / 2;
        return (t + 1 + 4 * operators + t + 3 * phases, 6 * operators + 2 * phases + 3 * (t / 2));
    }
}
