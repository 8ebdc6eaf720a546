using System.Text.Json.Nodes;
using QuantumRayTracing.Rendering;

namespace QuantumRayTracing.Cluster;

/// <summary>
/// What a worker runs requests on: image parts of the seeded engines (<see cref="PartRequest"/>) in this process, Q# chunks
/// on its Node bridges. Its capacity is the bridges': a render keeps that many parts in flight on it.
/// </summary>
public sealed class WorkerExecutor(IChunkExecutor bridges) : IChunkExecutor
{
    private readonly PartCache _parts = new();

    public int Capacity => bridges.Capacity;

    public Task<JsonNode> Execute(JsonObject request) =>
        PartRequest.Is(request) ? Task.Run(() => PartRequest.Run(request, _parts)) : bridges.Execute(request);
}
