namespace QuantumRayTracing.Cluster;

/// <summary>
/// One worker's bridges, reached through the cluster: the grain's key is the worker's silo address, so each
/// worker has exactly one and a render chooses which worker runs a chunk.
/// </summary>
public interface IChunkWorker : IGrainWithStringKey
{
    /// <summary>Runs one bridge request (a JSON line of the bridge protocol, unchanged) on one of the worker's bridges.</summary>
    Task<ChunkReply> Run(string request);

    /// <summary>How many bridges the worker has and how many are busy.</summary>
    Task<WorkerLoad> Load();
}

/// <summary>
/// The bridge's answer to one request: its result as JSON, or the failure the bridge reported, carried as
/// data so the render raises the same exception the local bridge would.
/// </summary>
[GenerateSerializer, Immutable]
public sealed record ChunkReply(
    [property: Id(0)] string? Result,
    [property: Id(1)] string? ErrorKind,
    [property: Id(2)] string? Message,
    [property: Id(3)] string? Code,
    [property: Id(4)] string? Location,
    [property: Id(5)] string? QSharpStack);

/// <summary>A worker's bridges and how many of them are running a chunk.</summary>
[GenerateSerializer, Immutable]
public sealed record WorkerLoad([property: Id(0)] int Bridges, [property: Id(1)] int Busy, [property: Id(2)] long Served);
