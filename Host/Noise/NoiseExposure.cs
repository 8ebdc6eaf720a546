using System.Text.Json.Nodes;

namespace QuantumRayTracing.Noise;

/// <summary>
/// A circuit's noise locations (one per qubit per operation, a measurement's before it) by gate kind and by which Pauli
/// errors can harm the run there (the pattern: "XYZ" all three, "XY" X and Y, "" none, …), as the bridge counts them from
/// the extracted circuit by the rules of Quantum/noise-exposure.mjs (docs/noise.md states them).
/// </summary>
public sealed record NoiseExposure(IReadOnlyDictionary<string, IReadOnlyDictionary<string, double>> ByKind)
{
    public static readonly NoiseExposure None = new(new Dictionary<string, IReadOnlyDictionary<string, double>>());

    /// <summary>Locations per harm pattern, every gate kind summed.</summary>
    public IReadOnlyDictionary<string, double> ByPattern =>
        ByKind.Values.SelectMany(p => p).GroupBy(p => p.Key).ToDictionary(g => g.Key, g => g.Sum(p => p.Value));

    /// <summary>All noise locations, whatever their pattern.</summary>
    public double Locations => ByKind.Values.Sum(p => p.Values.Sum());

    /// <summary>Locations of one gate kind.</summary>
    public double LocationsOf(string kind) => ByKind.TryGetValue(kind, out var p) ? p.Values.Sum() : 0;

    /// <summary>
    /// Harmful errors expected per unit of per-gate error under depolarizing noise: a third per harmful Pauli of each
    /// location. Divided by <see cref="Locations"/> it is the circuit's harmful share.
    /// </summary>
    public double HarmWeight => ByPattern.Sum(p => p.Value * p.Key.Length / 3.0);

    /// <summary>The same for one gate kind.</summary>
    public double HarmWeightOf(string kind) => ByKind.TryGetValue(kind, out var p) ? p.Sum(q => q.Value * q.Key.Length / 3.0) : 0;

    /// <summary>
    /// The probability that no harmful error occurs under <paramref name="noise"/>: Φ = Π over locations of
    /// (1 − the summed probabilities of the Paulis harmful there).
    /// </summary>
    public double Fidelity(NoiseModel noise)
    {
        if (noise.PerGate <= 0) return 1.0;
        var log = 0.0;
        foreach (var (pattern, count) in ByPattern)
        {
            var harmful = (pattern.Contains('X') ? noise.Px : 0) + (pattern.Contains('Y') ? noise.Py : 0) + (pattern.Contains('Z') ? noise.Pz : 0);
            if (harmful > 0) log += count * Math.Log(1 - Math.Min(harmful, 1 - 1e-12));
        }
        return Math.Exp(log);
    }

    public static NoiseExposure operator +(NoiseExposure a, NoiseExposure b) => Combine(a, b, 1);

    public static NoiseExposure operator -(NoiseExposure a, NoiseExposure b) => Combine(a, b, -1);

    public static NoiseExposure operator *(double k, NoiseExposure a) =>
        new(a.ByKind.ToDictionary(p => p.Key, p => (IReadOnlyDictionary<string, double>)p.Value.ToDictionary(q => q.Key, q => k * q.Value)));

    private static NoiseExposure Combine(NoiseExposure a, NoiseExposure b, double sign)
    {
        static double Of(NoiseExposure e, string kind, string pattern) =>
            e.ByKind.TryGetValue(kind, out var p) && p.TryGetValue(pattern, out var n) ? n : 0;
        var kinds = a.ByKind.Keys.Union(b.ByKind.Keys);
        return new(kinds.ToDictionary(k => k, k =>
        {
            var patterns = (a.ByKind.GetValueOrDefault(k)?.Keys ?? []).Union(b.ByKind.GetValueOrDefault(k)?.Keys ?? []);
            return (IReadOnlyDictionary<string, double>)patterns.ToDictionary(p => p, p => Of(a, k, p) + sign * Of(b, k, p));
        }));
    }

    /// <summary>The bridge summary's <c>exposure</c> part: {kind: {pattern: count}}.</summary>
    public static NoiseExposure Parse(JsonNode exposure) =>
        new(exposure.AsObject().ToDictionary(p => p.Key, p =>
            (IReadOnlyDictionary<string, double>)p.Value!.AsObject().ToDictionary(q => q.Key, q => q.Value!.GetValue<double>())));

    public JsonObject ToJson() => new(ByKind.OrderBy(p => p.Key, StringComparer.Ordinal).Select(p => KeyValuePair.Create(p.Key,
        (JsonNode?)new JsonObject(p.Value.OrderBy(q => q.Key, StringComparer.Ordinal).Select(q => KeyValuePair.Create(q.Key, (JsonNode?)q.Value))))));
}
