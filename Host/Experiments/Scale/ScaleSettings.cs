using QuantumRayTracing.Engines;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// What `bench scale` measures: `render` of <paramref name="SceneFile"/> at each of <paramref name="Sizes"/> (square) on
/// each of <paramref name="Engines"/>, each in a process of its own so that its peak memory is its own.
/// </summary>
public sealed record ScaleSettings(string SceneFile, IReadOnlyList<int> Sizes, IReadOnlyList<EngineKind> Engines, ulong Seed)
{
    public static readonly int[] DefaultSizes = [128, 256, 512, 1024, 2048, 4096, 8192];

    public static readonly EngineKind[] DefaultEngines = [EngineKind.Classical, EngineKind.Bvh, EngineKind.Analytic];
}
