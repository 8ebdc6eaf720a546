using System.Text.Json;
using System.Text.Json.Nodes;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Output;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// An image part as a cluster worker receives it, in the bridge protocol's shape: <c>{"method": "renderPart", ...}</c> with the
/// scene, the engine, the part's options and window; and the part's result as the worker returns it: the part's image bytes,
/// its passes' metrics and its expected wrong pixels. Doubles are written shortest-exact, so the worker renders the same
/// scene and options bit for bit, and so the same image.
/// </summary>
public static class PartRequest
{
    public const string Method = "renderPart";

    private static readonly JsonSerializerOptions Json = JsonSerializerOptions.Default;

    // What a part needs of an engine: its kind and QSearch's options, and its noise. Workers and the qubit limit belong to
    // the Q# engines, whose chunks go to the cluster one Grover run at a time, not as parts.
    private sealed record PartEngine(EngineKind Kind, QSearchOptions Search, NoiseModel? Noise, NoiseOracle NoiseOracle, bool IdealPlan, DeviceNoiseModel? Device);

    /// <summary>The scene as parts carry it (written once per render, sent with every part).</summary>
    public static string SceneText(Scene scene) => JsonSerializer.Serialize(scene, Json);

    public static JsonObject Of(string sceneText, EngineSetup engine, RenderOptions options, ImageWindow? window) => new()
    {
        ["method"] = Method,
        ["scene"] = sceneText,
        ["engine"] = JsonSerializer.SerializeToNode(new PartEngine(engine.Kind, engine.Search, engine.Noise, engine.NoiseOracle, engine.IdealPlan, engine.Device), Json),
        ["options"] = JsonSerializer.SerializeToNode(options, Json),
        ["window"] = window is { } w ? JsonSerializer.SerializeToNode(w, Json) : null,
    };

    /// <summary>Whether a worker's request is an image part rather than a Q# chunk.</summary>
    public static bool Is(JsonObject request) => request["method"]?.GetValue<string>() == Method;

    /// <summary>
    /// Renders the part a request names, here (<see cref="LocalParts"/>), and returns its result. A request this program
    /// cannot read is a <see cref="BridgeRequestException"/>: the render fails with it rather than trying another worker.
    /// </summary>
    public static JsonNode Run(JsonObject request, PartCache cache)
    {
        ArgumentNullException.ThrowIfNull(cache);
        LocalParts parts;
        RenderOptions options;
        ImageWindow? window;
        try
        {
            var sceneText = Field(request, "scene").GetValue<string>();
            var engineNode = Field(request, "engine");
            parts = cache.For(sceneText + "\n" + engineNode.ToJsonString(), () =>
            {
                var engine = engineNode.Deserialize<PartEngine>(Json) ?? throw new JsonException("'engine' is null");
                var scene = JsonSerializer.Deserialize<Scene>(sceneText, Json) ?? throw new JsonException("'scene' is null");
                return new LocalParts(scene, new EngineSetup(engine.Kind, engine.Search, Noise: engine.Noise, NoiseOracle: engine.NoiseOracle, IdealPlan: engine.IdealPlan, Device: engine.Device));
            });
            options = Field(request, "options").Deserialize<RenderOptions>(Json) ?? throw new JsonException("'options' is null");
            window = request["window"]?.Deserialize<ImageWindow>(Json);
        }
        catch (Exception e) when (e is JsonException or InvalidOperationException or ArgumentException or NotSupportedException)
        {
            throw new BridgeRequestException($"{Method}: the request cannot be read ({e.Message})");
        }
        var part = parts.Render(options, window, null);
        return new JsonObject
        {
            ["width"] = part.Image.Width,
            ["height"] = part.Image.Height,
            ["pixels"] = Convert.ToBase64String(part.Image.Pixels),
            ["passes"] = JsonSerializer.SerializeToNode(part.Passes, Json),
            ["budget"] = JsonSerializer.SerializeToNode(part.Budget, Json),
            ["light"] = part.LightError is { } light ? JsonSerializer.SerializeToNode(light, Json) : null,
        };
    }

    private static JsonNode Field(JsonObject request, string name) => request[name] ?? throw new JsonException($"no '{name}'");

    /// <summary>The part a worker returned, as the render that sent it reads it.</summary>
    public static RenderResult ReadResult(JsonNode reply)
    {
        var image = RgbImage.FromPixels(reply["width"]!.GetValue<int>(), reply["height"]!.GetValue<int>(), Convert.FromBase64String(reply["pixels"]!.GetValue<string>()));
        var passes = reply["passes"]!.Deserialize<PassMetrics[]>(Json)!;
        return new RenderResult(image, passes) { Budget = reply["budget"]!.Deserialize<AccuracyBudget>(Json)!, LightError = reply["light"]?.Deserialize<Metrics.LightError>(Json) };
    }
}
