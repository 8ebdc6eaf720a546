namespace QuantumRayTracing.Rendering;

/// <summary>
/// Work whose items are independent but whose results must be taken in order (points appended to a list, radiance
/// added to a pixel): the items are computed on all cores a chunk at a time, then taken one by one in index order, so
/// the outcome is the sequential loop's, bit for bit, with only one chunk of results held at once.
/// </summary>
public static class InOrder
{
    /// <summary>Items per chunk: enough to keep every core busy, few enough to hold little.</summary>
    public const int ChunkSize = 1 << 14;

    /// <summary>Calls <paramref name="take"/>(i, <paramref name="compute"/>(i)) for i = 0 … count − 1 in order; compute must only read shared state.</summary>
    public static void Run<T>(int count, Func<int, T> compute, Action<int, T> take)
    {
        var results = new T[Math.Min(count, ChunkSize)];
        for (var start = 0; start < count; start += ChunkSize)
        {
            var (from, length) = (start, Math.Min(ChunkSize, count - start));
            Parallel.For(0, length, k => results[k] = compute(from + k));
            for (var k = 0; k < length; k++) take(from + k, results[k]);
        }
    }
}
