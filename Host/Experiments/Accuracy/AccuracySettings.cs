using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// What `bench accuracy` measures: random scenes of every kind at <paramref name="Sizes"/>² with seeds 1..<paramref name="Seeds"/>
/// (the 4,000-rectangle scenes up to <paramref name="DeepSize"/>²), and <paramref name="Qornell"/>, `render`'s built-in scene.
/// </summary>
public sealed record AccuracySettings(IReadOnlyList<int> Sizes, int Seeds, int DeepSize, Scene Qornell);
