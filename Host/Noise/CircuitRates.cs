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
}
