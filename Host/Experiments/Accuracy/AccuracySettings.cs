using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// What `bench accuracy` measures: random scenes of every kind at <paramref name="Sizes"/>² with seeds 1..<paramref name="Seeds"/>
/// (the 4,000-rectangle scenes up to <paramref name="DeepSize"/>²), <paramref name="Qornell"/>, `render`'s built-in scene, and
/// scattered scenes of <see cref="Growth"/> rectangles for where the budget spends its queries (only those with <see cref="GrowthOnly"/>),
/// the default's spread over their seeds 1..<see cref="GrowthSeeds"/> beside it.
/// </summary>
public sealed record AccuracySettings(IReadOnlyList<int> Sizes, int Seeds, int DeepSize, Scene Qornell)
{
    public static readonly int[] DefaultGrowth = [64, 512, 1024, 4096];

    public IReadOnlyList<int> Growth { get; init; } = DefaultGrowth;

    public bool GrowthOnly { get; init; }

    public const int DefaultGrowthSeeds = 10;

    public int GrowthSeeds { get; init; } = DefaultGrowthSeeds;
}
