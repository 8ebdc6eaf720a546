using System.Text.Json.Nodes;
using Orleans.Concurrency;
using QuantumRayTracing.Bridge;

namespace QuantumRayTracing.Cluster;

/// <summary>
/// The grain a worker serves chunks through: it hands each request to the worker's bridges and turns the
/// bridge's failures into a <see cref="ChunkReply"/>. Reentrant, so all the worker's bridges are busy at once.
/// </summary>
[SiloKeyedPlacement, Reentrant]
public sealed class ChunkWorker(IChunkExecutor executor, WorkerStatistics statistics) : Grain, IChunkWorker
{
    public async Task<ChunkReply> Run(string request)
    {
        statistics.Started();
        try
        {
            var result = await executor.Execute((JsonObject)JsonNode.Parse(request)!);
            return new ChunkReply(result.ToJsonString(), null, null, null, null, null);
        }
        catch (QSharpException e)
        {
            return new ChunkReply(null, "qsharp", e.Message, e.Code, e.Location, e.QSharpStack);
        }
        catch (BridgeRequestException e)
        {
            return new ChunkReply(null, "request", e.Message, null, null, null);
        }
        catch (BridgeException e)
        {
            return new ChunkReply(null, "bridge", e.Message, null, null, null);
        }
        finally
        {
            statistics.Finished();
        }
    }

    public Task<WorkerLoad> Load() => Task.FromResult(new WorkerLoad(executor.Capacity, statistics.Busy, statistics.Served));
}

/// <summary>A worker's running and served chunk counts, for its load log and <see cref="IChunkWorker.Load"/>.</summary>
public sealed class WorkerStatistics
{
    private int _busy;
    private long _served;

    public int Busy => Volatile.Read(ref _busy);

    public long Served => Interlocked.Read(ref _served);

    public void Started() => Interlocked.Increment(ref _busy);

    public void Finished()
    {
        Interlocked.Decrement(ref _busy);
        Interlocked.Increment(ref _served);
    }
}
