using System.Text.Json.Nodes;

namespace QuantumRayTracing.Cluster;

/// <summary>What a worker runs requests on: its Node bridges (<see cref="WorkerBridges"/>).</summary>
public interface IChunkExecutor
{
    /// <summary>How many requests the worker runs at once.</summary>
    int Capacity { get; }

    /// <summary>Runs one bridge request and returns its result, throwing what the bridge throws.</summary>
    Task<JsonNode> Execute(JsonObject request);
}
