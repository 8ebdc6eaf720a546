using System.Text.Json.Nodes;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Bridge;

/// <summary>
/// Somewhere other than a local Node process that serves bridge requests (a cluster's workers): it takes a
/// request as the bridge protocol writes it and returns the bridge's result, or throws what the bridge would.
/// </summary>
public interface IBridgeTransport
{
    JsonNode Send(JsonObject request);

    /// <summary>Where the requests run, for reports.</summary>
    RunPlace Place { get; }
}
