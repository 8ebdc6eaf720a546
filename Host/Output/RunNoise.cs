using QuantumRayTracing.Engines;
using QuantumRayTracing.Noise;

namespace QuantumRayTracing.Output;

/// <summary>
/// The noise model a result was obtained under, as its reports name it: a model name and its rates (for Pauli
/// noise px, py, pz per gate and the qubit loss) and how the printed results describe it. <see cref="None"/> for a
/// noiseless run.
/// </summary>
public sealed record RunNoise(string Model, IReadOnlyDictionary<string, double>? Rates = null, string? Description = null)
{
    public static readonly RunNoise None = new("none");

    /// <summary>The record of <paramref name="noise"/> on the engine <paramref name="kind"/>: the one place results take it from.</summary>
    /// <param name="kind">The engine.</param>
    /// <param name="noise">The noise it ran under.</param>
    /// <param name="description">The noise model as the run printed it; null: as the engine names it over the lookup oracle.</param>
    public static RunNoise Of(EngineKind kind, NoiseModel noise, string? description = null)
    {
        if (noise.IsNoiseless) return None;
        var rates = new Dictionary<string, double> { ["px"] = noise.Px, ["py"] = noise.Py, ["pz"] = noise.Pz, ["qubitLoss"] = noise.QubitLoss };
        return new RunNoise(kind.ApproximatesNoise ? "pauli, depolarizing approximation" : "pauli", rates, description ?? EngineFactory.NoiseDescription(kind, noise));
    }

    /// <summary>The record of a run under <paramref name="device"/> when given, else under <paramref name="noise"/>, described as the run printed it.</summary>
    public static RunNoise Of(EngineKind kind, NoiseModel noise, DeviceNoiseModel? device, string description) =>
        device is null ? Of(kind, noise, description) : Of(kind, device, description);

    /// <summary>The record of a device model: its one- and two-qubit rates and readout flips; the description as the run printed it, or the model's own.</summary>
    public static RunNoise Of(EngineKind kind, DeviceNoiseModel device, string? description = null) =>
        new(kind.ApproximatesNoise ? "device, depolarizing approximation" : "device",
            new Dictionary<string, double> { ["oneQubit"] = device.OneQubit, ["twoQubit"] = device.TwoQubit, ["readZeroAsOne"] = device.ReadZeroAsOne, ["readOneAsZero"] = device.ReadOneAsZero },
            description ?? device.Description());
}
