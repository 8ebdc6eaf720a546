using System.Text.Json.Nodes;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Noise;

/// <summary>
/// The gate-level oracle's noise exposure per circuit shape (N and coordinate bits), traced once by
/// <c>qrt bench noise --parts exposure</c> and kept in gate-level-exposure.json beside this file (an embedded
/// resource), so an analytic render under noise starts no bridge.
/// </summary>
public static class GateLevelExposureTable
{
    public const string ResourceName = "QuantumRayTracing.Noise.gate-level-exposure.json";

    private static readonly Lazy<IReadOnlyDictionary<string, GateLevelExposure>> Loaded = new(Load);

    /// <summary>The built-in table by shape.</summary>
    public static IReadOnlyDictionary<string, GateLevelExposure> Entries => Loaded.Value;

    /// <summary>The scene's circuit, or null when its shape was not traced.</summary>
    public static GateLevelExposure? For(Scene scene) => Entries.GetValueOrDefault(GateLevelExposure.KeyOf(scene));

    /// <summary>The shapes the table holds.</summary>
    public static IReadOnlyCollection<string> Keys => Entries.Keys.ToArray();

    private static IReadOnlyDictionary<string, GateLevelExposure> Load()
    {
        using var stream = typeof(GateLevelExposureTable).Assembly.GetManifestResourceStream(ResourceName)
            ?? throw new InvalidOperationException($"the embedded resource {ResourceName} is missing");
        return Parse(JsonNode.Parse(stream)!);
    }

    public static IReadOnlyDictionary<string, GateLevelExposure> Parse(JsonNode table) =>
        table.AsObject().ToDictionary(p => p.Key, p => GateLevelExposure.Parse(p.Value!));

    public static JsonObject ToJson(IEnumerable<(string Key, GateLevelExposure Exposure)> entries) =>
        new(entries.OrderBy(e => e.Key, StringComparer.Ordinal).Select(e => KeyValuePair.Create(e.Key, (JsonNode?)e.Exposure.ToJson())));
}
