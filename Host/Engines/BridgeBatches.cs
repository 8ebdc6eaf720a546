using System.Text.Json;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Engines;

/// <summary>
/// Runs a batch of Grover requests as Q# calls on a bridge pool: the batch is cut into consecutive
/// chunks, each chunk is one call on its own bridge, and the chunks run on all workers at once.
/// Shared by the Q# engines, which differ in the call they build and in what a request costs.
/// </summary>
internal static class BridgeBatches
{
    /// <summary>
    /// One measured index per request, in order, each checked to lie below its request's N; under noise, below
    /// 2^ceil(log2 N) (a flipped top bit can read an index past N, as a device would).
    /// </summary>
    /// <remarks><paramref name="operation"/> names the Q# operation in error messages; <paramref name="expression"/>
    /// builds the Q# call of one chunk, which must return one index per request. <paramref name="noise"/> runs
    /// the calls on the noisy simulator unless it is the ideal model.</remarks>
    public static int[] Measure(
        BridgePool pool,
        IReadOnlyList<GroverRequest> requests,
        ChunkLimits limits,
        string operation,
        Func<IReadOnlyList<GroverRequest>, string> expression,
        NoiseModel? noise = null)
    {
        var noisy = noise is { IsNoiseless: false };
        var measured = new int[requests.Count];
        if (requests.Count == 0) return measured;
        pool.ForEach(Chunks(requests, pool.Workers, limits), (chunk, bridge) =>
        {
            var slice = Enumerable.Range(chunk.Start, chunk.Length).Select(k => requests[k]).ToArray();
            var shots = bridge.Run(expression(slice), noise: noise);
            var indices = JsonSerializer.Deserialize<int[]>(shots[0])
                ?? throw new BridgeException($"{operation} returned no value");
            if (indices.Length != slice.Length)
                throw new BridgeException($"{operation} returned {indices.Length} indices for {slice.Length} requests");
            for (var k = 0; k < slice.Length; k++)
            {
                var readable = noisy ? 1 << SearchRegisters.For(slice[k].Marked.Count).IndexQubits : slice[k].Marked.Count;
                if (indices[k] < 0 || indices[k] >= readable)
                    throw new BridgeException($"{operation} measured index {indices[k]} outside 0..{readable - 1}");
                measured[chunk.Start + k] = indices[k];
            }
        });
        return measured;
    }

    /// <summary>
    /// Consecutive chunks of at most <see cref="ChunkLimits.MaxRequests"/> requests, as equal as whole
    /// waves over the workers allow, closed early when the next request would take the chunk's cost past
    /// <see cref="ChunkLimits.MaxCost"/> (a request costing more than that gets a chunk of its own).
    /// </summary>
    public static IReadOnlyList<(int Start, int Length)> Chunks(IReadOnlyList<GroverRequest> requests, int workers, ChunkLimits limits)
    {
        // Equal chunks in whole waves over the workers: 1024 requests on 2 workers at most 500 per call
        // go as 4 chunks of 256, not 500 + 500 + 24, which would leave one worker idle for a wave.
        var perWave = (long)workers * limits.MaxRequests;
        var waves = (int)((requests.Count + perWave - 1) / perWave);
        var countLimit = (requests.Count + waves * workers - 1) / (waves * workers);
        var chunks = new List<(int Start, int Length)>();
        var (start, cost) = (0, 0.0);
        for (var k = 0; k < requests.Count; k++)
        {
            var next = limits.Cost(requests[k]);
            if (k > start && (k - start == countLimit || cost + next > limits.MaxCost))
            {
                chunks.Add((start, k - start));
                (start, cost) = (k, 0.0);
            }
            cost += next;
        }
        chunks.Add((start, requests.Count - start));
        return chunks;
    }
}

/// <summary>How much one Q# call may carry: a request count, and a budget in the engine's own cost unit.</summary>
internal sealed record ChunkLimits(int MaxRequests, Func<GroverRequest, double> Cost, double MaxCost)
{
    /// <summary>Only a request count: every request costs the same.</summary>
    public static ChunkLimits Count(int maxRequests) => new(maxRequests, _ => 1, double.PositiveInfinity);

    public int MaxRequests { get; } = MaxRequests >= 1 ? MaxRequests : throw new ArgumentOutOfRangeException(nameof(MaxRequests), MaxRequests, "at least one request per call");
}
