using System.Text.Json.Nodes;

namespace QuantumRayTracing.Noise;

/// <summary>
/// A circuit's noise locations (one per qubit per operation, a measurement's before it) by gate kind and by which Pauli
/// errors can harm the run there (the pattern: "XYZ" all three, "XY" X and Y, "" none, …), as the bridge counts them from
/// the extracted circuit by the rules of Quantum/noise-exposure.mjs (docs/noise.md states them); and, when given, the
/// graded harm per gate kind and Pauli (<paramref name="Harm"/>: the summed h of X, Y and Z over the kind's locations,
/// Quantum/noise-harm.mjs), which <see cref="Fidelity"/> then uses instead of the patterns.
/// </summary>
public sealed record NoiseExposure(IReadOnlyDictionary<string, IReadOnlyDictionary<string, double>> ByKind, IReadOnlyDictionary<string, IReadOnlyDictionary<string, double>>? Harm = null)
{
    public static readonly NoiseExposure None = new(new Dictionary<string, IReadOnlyDictionary<string, double>>());

    /// <summary>The same locations with the harm only the patterns give (every harmful Pauli a whole harm).</summary>
    public NoiseExposure Ungraded => this with { Harm = null };

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
    public double HarmWeight => Harm is { } graded ? graded.Values.Sum(h => h.Values.Sum()) / 3.0 : ByPattern.Sum(p => p.Value * p.Key.Length / 3.0);

    /// <summary>The same for one gate kind.</summary>
    public double HarmWeightOf(string kind) =>
        Harm is { } graded ? (graded.TryGetValue(kind, out var h) ? h.Values.Sum() / 3.0 : 0)
        : ByKind.TryGetValue(kind, out var p) ? p.Sum(q => q.Value * q.Key.Length / 3.0) : 0;

    /// <summary>
    /// The probability that no harmful error occurs under <paramref name="noise"/>: Φ = Π over locations of
    /// (1 − the summed probabilities of the Paulis harmful there).
    /// </summary>
    public double Fidelity(NoiseModel noise)
    {
        if (noise.PerGate <= 0) return 1.0;
        if (Harm is { } graded)
        {
            // Each location's Pauli P contributes (1 − p_P)^h: a whole harm h = 1 is the pattern rule's factor.
            return Math.Exp(graded.Values.Sum(h =>
                new PauliWeights(h.GetValueOrDefault("X"), h.GetValueOrDefault("Y"), h.GetValueOrDefault("Z")).LogSurvival(noise)));
        }
        var log = 0.0;
        foreach (var (pattern, count) in ByPattern)
        {
            var harmful = (pattern.Contains('X') ? noise.Px : 0) + (pattern.Contains('Y') ? noise.Py : 0) + (pattern.Contains('Z') ? noise.Pz : 0);
            if (harmful > 0) log += count * Math.Log(1 - Math.Min(harmful, 1 - 1e-12));
        }
        return Math.Exp(log);
    }

    /// <summary>
    /// The one depolarizing-like model that leaves this circuit's harm as <paramref name="rates"/> leave it, Pauli by Pauli: p_P
    /// with ln(1 − p_P) the mean of ln(1 − p_P(kind)) over gate kinds, each weighted by the harm its locations carry from P (the
    /// graded harm; without it, the locations where P harms). Exact for <see cref="Fidelity"/>; for anything else that weighs
    /// these locations differently from their harm (the index register's channels), an approximation.
    /// </summary>
    public NoiseModel Effective(CircuitRates rates)
    {
        ArgumentNullException.ThrowIfNull(rates);
        if (rates.Uniform is { } uniform) return uniform;
        double Rate(string pauli, Func<NoiseModel, double> rate)
        {
            var (weight, log) = (0.0, 0.0);
            foreach (var kind in ByKind.Keys.Union(Harm?.Keys ?? []))
            {
                var w = Harm is { } graded ? graded.GetValueOrDefault(kind)?.GetValueOrDefault(pauli) ?? 0
                    : ByKind[kind].Where(p => p.Key.Contains(pauli, StringComparison.Ordinal)).Sum(p => p.Value);
                weight += w;
                log += w * Math.Log(1 - Math.Min(rate(rates.For(kind)), 1 - 1e-12));
            }
            return weight > 0 ? 1 - Math.Exp(log / weight) : 0;
        }
        return new NoiseModel(Rate("X", n => n.Px), Rate("Y", n => n.Py), Rate("Z", n => n.Pz));
    }

    public static NoiseExposure operator +(NoiseExposure a, NoiseExposure b) => Combine(a, b, 1);

    public static NoiseExposure operator -(NoiseExposure a, NoiseExposure b) => Combine(a, b, -1);

    public static NoiseExposure operator *(double k, NoiseExposure a) => new(Scale(k, a.ByKind), a.Harm is { } h ? Scale(k, h) : null);

    /// <summary>Sums or differences; graded harm only when both sides have it.</summary>
    private static NoiseExposure Combine(NoiseExposure a, NoiseExposure b, double sign) =>
        new(Combine(a.ByKind, b.ByKind, sign), a.Harm is { } ha && b.Harm is { } hb ? Combine(ha, hb, sign) : null);

    private static IReadOnlyDictionary<string, IReadOnlyDictionary<string, double>> Scale(double k, IReadOnlyDictionary<string, IReadOnlyDictionary<string, double>> table) =>
        table.ToDictionary(p => p.Key, p => (IReadOnlyDictionary<string, double>)p.Value.ToDictionary(q => q.Key, q => k * q.Value));

    private static IReadOnlyDictionary<string, IReadOnlyDictionary<string, double>> Combine(
        IReadOnlyDictionary<string, IReadOnlyDictionary<string, double>> a, IReadOnlyDictionary<string, IReadOnlyDictionary<string, double>> b, double sign)
    {
        static double Of(IReadOnlyDictionary<string, IReadOnlyDictionary<string, double>> e, string kind, string key) =>
            e.TryGetValue(kind, out var p) && p.TryGetValue(key, out var n) ? n : 0;
        var kinds = a.Keys.Union(b.Keys);
        return kinds.ToDictionary(k => k, k =>
        {
            var keys = (a.GetValueOrDefault(k)?.Keys ?? []).Union(b.GetValueOrDefault(k)?.Keys ?? []);
            return (IReadOnlyDictionary<string, double>)keys.ToDictionary(p => p, p => Of(a, k, p) + sign * Of(b, k, p));
        });
    }

    /// <summary>The bridge summary's <c>exposure</c> part, {kind: {pattern: count}}, and its <c>harm</c> part, {kind: {X, Y, Z}}, if any.</summary>
    public static NoiseExposure Parse(JsonNode exposure, JsonNode? harm = null) => new(Table(exposure), harm is null ? null : Table(harm));

    private static IReadOnlyDictionary<string, IReadOnlyDictionary<string, double>> Table(JsonNode node) =>
        node.AsObject().ToDictionary(p => p.Key, p =>
            (IReadOnlyDictionary<string, double>)p.Value!.AsObject().ToDictionary(q => q.Key, q => q.Value!.GetValue<double>()));

    public JsonObject ToJson() => Json(ByKind);

    /// <summary>The graded harm as JSON, or null when there is none.</summary>
    public JsonObject? HarmToJson() => Harm is { } h ? Json(h) : null;

    private static JsonObject Json(IReadOnlyDictionary<string, IReadOnlyDictionary<string, double>> table) => new(table.OrderBy(p => p.Key, StringComparer.Ordinal).Select(p => KeyValuePair.Create(p.Key,
        (JsonNode?)new JsonObject(p.Value.OrderBy(q => q.Key, StringComparer.Ordinal).Select(q => KeyValuePair.Create(q.Key, (JsonNode?)Math.Round(q.Value, 6)))))));
}
