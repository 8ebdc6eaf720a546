using QuantumRayTracing.Search;

namespace QuantumRayTracing.Tests.Engines;

/// <summary>A Grover request described by (N, marked, r), with the cases every engine is checked on.</summary>
public sealed record GroverCase(int Count, int[] Marked, int Iterations, string Why)
{
    public GroverRequest Request => new(new MarkedSet(Count, Marked), Iterations);

    public override string ToString() => $"N={Count} t={Marked.Length} r={Iterations} ({Why})";

    public static readonly GroverCase[] Hard =
    [
        new(8, [5], 2, "near-optimal r"),
        new(8, [5], 1, "under-rotated"),
        new(64, [17], 3, "N = 64, r = 3"),
        new(64, [17], 6, "N = 64, optimal r"),
        new(16, [], 3, "t = 0"),
        new(8, [0, 2, 5, 7], 1, "t = N/2"),
        new(8, [0, 1, 2, 3, 4, 5, 6, 7], 2, "t = N"),
        new(8, [1, 3, 4, 5, 6], 1, "t > N/2"),
        new(1, [0], 0, "N = 1, sample"),
        new(1, [0], 3, "N = 1, t = 1"),
        new(1, [], 2, "N = 1, t = 0"),
        new(5, [3], 1, "N = 5, not a power of two"),
        new(12, [2, 9], 1, "N = 12, not a power of two"),
        new(12, [2, 9], 0, "N = 12, sample"),
    ];
}
