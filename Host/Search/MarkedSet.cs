namespace QuantumRayTracing.Search;

/// <summary>
/// A search space of <see cref="Count"/> indices and the sorted, distinct indices the oracle marks:
/// what the lookup-table oracle needs from the host.
/// </summary>
public sealed class MarkedSet
{
    private readonly int[] _indices;

    /// <param name="count">Number of indices N ≥ 1.</param>
    /// <param name="indices">Marked indices, each in [0, N), in any order, without repeats.</param>
    public MarkedSet(int count, IEnumerable<int> indices)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(count, 1);
        var sorted = indices.ToArray();
        Array.Sort(sorted);
        for (var k = 0; k < sorted.Length; k++)
        {
            if (sorted[k] < 0 || sorted[k] >= count)
                throw new ArgumentOutOfRangeException(nameof(indices), $"marked index {sorted[k]} is outside 0..{count - 1}");
            if (k > 0 && sorted[k] == sorted[k - 1])
                throw new ArgumentException($"marked index {sorted[k]} is listed twice", nameof(indices));
        }
        Count = count;
        _indices = sorted;
    }

    // Indices already sorted, distinct and in range (a ray table's accepted rows): taken as they are.
    private MarkedSet(int count, int[] sorted) => (Count, _indices) = (count, sorted);

    /// <summary>A set from indices the caller guarantees ascending, distinct and in [0, <paramref name="count"/>): no copy, no check.</summary>
    internal static MarkedSet FromAscending(int count, int[] ascending) => new(count, ascending);

    /// <summary>N, the number of indices searched.</summary>
    public int Count { get; }

    /// <summary>t, the number of marked indices.</summary>
    public int MarkedCount => _indices.Length;

    /// <summary>The marked indices in ascending order.</summary>
    public ReadOnlySpan<int> Indices => _indices;

    /// <summary>The classical test f(i): is index <paramref name="index"/> marked.</summary>
    public bool Contains(int index) => Array.BinarySearch(_indices, index) >= 0;
}
