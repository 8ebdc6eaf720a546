namespace QuantumRayTracing.Experiments;

/// <summary>
/// What `bench bvh-comparison` measures: renders at <paramref name="Size"/>² with <paramref name="Seed"/> of the Qornell
/// box at <paramref name="QornellSizes"/> primitives, the Depth Complexity scenes and scattered random scenes at
/// <paramref name="RandomSizes"/> primitives.
/// </summary>
public sealed record BvhComparisonSettings(int Size, ulong Seed, IReadOnlyList<int> QornellSizes, IReadOnlyList<int> RandomSizes)
{
    public static readonly int[] DefaultQornellSizes = [8, 16, 32, 64, 128, 256, 512, 1024, 2048, 4096];

    public static readonly int[] DefaultRandomSizes = [64, 512, 4096];
}
