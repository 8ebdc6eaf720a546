namespace QuantumRayTracing.Noise;

/// <summary>
/// The Pauli noise of a circuit by where it acts: after one-qubit gates, on each qubit after gates on two or more, before
/// each measurement; and the readout error that flips a measured bit classically. A <see cref="NoiseModel"/> is one rate
/// everywhere and no readout error; a <see cref="DeviceNoiseModel"/> its two gate rates, a clean measurement and its readout.
/// </summary>
public sealed record CircuitRates(NoiseModel OneQubit, NoiseModel TwoQubit, NoiseModel Measurement, double ReadZeroAsOne = 0, double ReadOneAsZero = 0)
{
    public static readonly CircuitRates Noiseless = Of(NoiseModel.None);

    public static CircuitRates Of(NoiseModel noise)
    {
        ArgumentNullException.ThrowIfNull(noise);
        return new(noise, noise, noise);
    }

    public static CircuitRates Of(DeviceNoiseModel device)
    {
        ArgumentNullException.ThrowIfNull(device);
        return new(NoiseModel.Depolarizing(device.OneQubit), NoiseModel.Depolarizing(device.TwoQubit), NoiseModel.None, device.ReadZeroAsOne, device.ReadOneAsZero);
    }

    public bool HasReadoutError => ReadZeroAsOne > 0 || ReadOneAsZero > 0;

    /// <summary>No gate noise and no readout error: the engines take their noiseless path.</summary>
    public bool IsNoiseless => OneQubit.IsNoiseless && TwoQubit.IsNoiseless && Measurement.IsNoiseless && !HasReadoutError;

    /// <summary>The one model acting everywhere when these rates are a <see cref="NoiseModel"/>'s; null when they differ by place or read with error.</summary>
    public NoiseModel? Uniform => OneQubit == TwoQubit && TwoQubit == Measurement && !HasReadoutError ? OneQubit : null;

    /// <summary>The same gate noise with a clean readout: what acts on the qubits before a measured bit is read.</summary>
    public CircuitRates GatesOnly => HasReadoutError ? this with { ReadZeroAsOne = 0, ReadOneAsZero = 0 } : this;

    /// <summary>
    /// The noise after a gate of <paramref name="kind"/> as circuit summaries name them ("H", "CX", "CCX", "SWAP", "M" for a
    /// measurement): a measurement's, a one-qubit gate's, or that of a gate on two or more qubits.
    /// </summary>
    public NoiseModel For(string kind) =>
        kind == "M" ? Measurement : NoiseLocations.QubitsOf(kind) >= 2 ? TwoQubit : OneQubit;
}
