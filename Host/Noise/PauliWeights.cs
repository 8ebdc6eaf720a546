using System.Text.Json.Nodes;

namespace QuantumRayTracing.Noise;

/// <summary>
/// A weight per Pauli error, X, Y and Z: how many locations' worth of each Pauli's probability acts on some quantity (a harm,
/// or a coherence's decay). Under <see cref="NoiseModel"/> the quantity survives with Π (1 − p_P)^weight.
/// </summary>
public sealed record PauliWeights(double X, double Y, double Z)
{
    public static readonly PauliWeights None = new(0, 0, 0);

    /// <summary>ln of the survival Π over Paulis of (1 − p_P)^weight.</summary>
    public double LogSurvival(NoiseModel noise)
    {
        static double Log(double p) => Math.Log(1 - Math.Min(p, 1 - 1e-12));
        return X * Log(noise.Px) + Y * Log(noise.Py) + Z * Log(noise.Pz);
    }

    /// <summary>A third of the summed weights: the effect per unit of per-gate error under depolarizing noise.</summary>
    public double Depolarizing => (X + Y + Z) / 3;

    public static PauliWeights operator +(PauliWeights a, PauliWeights b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z);

    public static PauliWeights operator *(double k, PauliWeights a) => new(k * a.X, k * a.Y, k * a.Z);

    public JsonObject ToJson() => new() { ["X"] = Math.Round(X, 6), ["Y"] = Math.Round(Y, 6), ["Z"] = Math.Round(Z, 6) };

    public static PauliWeights Parse(JsonNode node) => new(node["X"]!.GetValue<double>(), node["Y"]!.GetValue<double>(), node["Z"]!.GetValue<double>());
}
