using System.Text.Json;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Engines;

/// <summary>
/// Runs a batch of Grover requests as Q# calls on a bridge pool: the batch is cut into chunks of at
/// most <c>maxRequestsPerCall</c> requests and at least one chunk per worker, each chunk is one call
/// on its own bridge, and the chunks run on all workers at once. Shared by the Q# engines, which
/// differ only in the call they build.
/// </summary>
internal static class BridgeBatches
{
    /// <summary>One measured index per request, in order, each checked to lie below its request's N.</summary>
    /// <remarks><paramref name="operation"/> names the Q# operation in error messages; <paramref name="expression"/>
    /// builds the Q# call of one chunk, which must return one index per request.</remarks>
    public static int[] Measure(
        BridgePool pool,
        IReadOnlyList<GroverRequest> requests,
        int maxRequestsPerCall,
        string operation,
        Func<IReadOnlyList<GroverRequest>, string> expression)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(maxRequestsPerCall, 1);
        var measured = new int[requests.Count];
        if (requests.Count == 0) return measured;
        var chunkSize = Math.Min(maxRequestsPerCall, (requests.Count + pool.Workers - 1) / pool.Workers);
        var chunks = Enumerable.Range(0, (requests.Count + chunkSize - 1) / chunkSize)
            .Select(c => (Start: c * chunkSize, Length: Math.Min(chunkSize, requests.Count - c * chunkSize)))
            .ToArray();
        pool.ForEach(chunks, (chunk, bridge) =>
        {
            var slice = Enumerable.Range(chunk.Start, chunk.Length).Select(k => requests[k]).ToArray();
            var shots = bridge.Run(expression(slice));
            var indices = JsonSerializer.Deserialize<int[]>(shots[0])
                ?? throw new BridgeException($"{operation} returned no value");
            if (indices.Length != slice.Length)
                throw new BridgeException($"{operation} returned {indices.Length} indices for {slice.Length} requests");
            for (var k = 0; k < slice.Length; k++)
            {
                if (indices[k] < 0 || indices[k] >= slice[k].Marked.Count)
                    throw new BridgeException($"{operation} measured index {indices[k]} outside 0..{slice[k].Marked.Count - 1}");
                measured[chunk.Start + k] = indices[k];
            }
        });
        return measured;
    }
}
