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
    /// the calls on the noisy simulator unless it is the ideal model; <paramref name="noisyReadout"/> accepts any register
    /// value when the noise is set inside the circuit instead (a device model).</remarks>
    public static int[] Measure(
        BridgePool pool,
        IReadOnlyList<GroverRequest> requests,
        ChunkLimits limits,
        string operation,
        Func<IReadOnlyList<GroverRequest>, string> expression,
        NoiseModel? noise = null,
        bool noisyReadout = false) =>
        Run(pool, requests, limits.MaxRequests, limits.Cost, limits.MaxCost, expression, (slice, value) =>
        {
            var indices = JsonSerializer.Deserialize<int[]>(value) ?? throw new BridgeException($"{operation} returned no value");
            if (indices.Length != slice.Count)
                throw new BridgeException($"{operation} returned {indices.Length} indices for {slice.Count} requests");
            for (var k = 0; k < slice.Count; k++) CheckIndex(operation, indices[k], slice[k], noisyReadout || noise is { IsNoiseless: false });
            return indices;
        }, noise);

    /// <summary>Throws unless <paramref name="index"/> lies in 0..N-1 of <paramref name="request"/> (under noise, in 0..2^n-1).</summary>
    public static void CheckIndex(string operation, int index, GroverRequest request, bool noisy)
    {
        var readable = noisy ? 1 << SearchRegisters.For(request.Marked.Count).IndexQubits : request.Marked.Count;
        if (index < 0 || index >= readable)
            throw new BridgeException($"{operation} measured index {index} outside 0..{readable - 1}");
    }

    /// <summary>
    /// One result per item, in order: the items are cut into chunks (<see cref="Chunks{T}"/>), each chunk is one
    /// Q# call built by <paramref name="expression"/> on a bridge of its own, and <paramref name="parse"/> turns the
    /// call's value into one result per item of the chunk. Every call runs under <paramref name="noise"/>.
    /// </summary>
    public static TResult[] Run<TItem, TResult>(
        BridgePool pool,
        IReadOnlyList<TItem> items,
        int maxItems,
        Func<TItem, double> cost,
        double maxCost,
        Func<IReadOnlyList<TItem>, string> expression,
        Func<IReadOnlyList<TItem>, string, TResult[]> parse,
        NoiseModel? noise = null)
    {
        var results = new TResult[items.Count];
        if (items.Count == 0) return results;
        pool.ForEach(Chunks(items, pool.Workers, maxItems, cost, maxCost), (chunk, bridge) =>
        {
            var slice = Enumerable.Range(chunk.Start, chunk.Length).Select(k => items[k]).ToArray();
            var values = parse(slice, bridge.Run(expression(slice), noise: noise)[0]);
            values.CopyTo(results, chunk.Start);
        });
        return results;
    }

    /// <summary>
    /// Consecutive chunks of at most <see cref="ChunkLimits.MaxRequests"/> requests, as equal as whole
    /// waves over the workers allow, closed early when the next request would take the chunk's cost past
    /// <see cref="ChunkLimits.MaxCost"/> (a request costing more than that gets a chunk of its own).
    /// </summary>
    public static IReadOnlyList<(int Start, int Length)> Chunks(IReadOnlyList<GroverRequest> requests, int workers, ChunkLimits limits) =>
        Chunks(requests, workers, limits.MaxRequests, limits.Cost, limits.MaxCost);

    /// <summary>The same cut for any items, with a count limit and a cost per item.</summary>
    public static IReadOnlyList<(int Start, int Length)> Chunks<T>(IReadOnlyList<T> requests, int workers, int maxItems, Func<T, double> itemCost, double maxCost)
    {
        // Equal chunks in whole waves over the workers: 1024 requests on 2 workers at most 500 per call
        // go as 4 chunks of 256, not 500 + 500 + 24, which would leave one worker idle for a wave.
        var perWave = (long)workers * maxItems;
        var waves = (int)((requests.Count + perWave - 1) / perWave);
        var countLimit = (requests.Count + waves * workers - 1) / (waves * workers);
        var chunks = new List<(int Start, int Length)>();
        var (start, cost) = (0, 0.0);
        for (var k = 0; k < requests.Count; k++)
        {
            var next = itemCost(requests[k]);
            if (k > start && (k - start == countLimit || cost + next > maxCost))
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
