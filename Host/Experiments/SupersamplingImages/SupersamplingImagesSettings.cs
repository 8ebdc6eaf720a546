namespace QuantumRayTracing.Experiments;

/// <summary>
/// What `bench supersampling-images` measures: every configuration with seeds 1..<paramref name="Seeds"/>, and the thesis's
/// tables at the output <paramref name="Sizes"/> (4x4 subpixels each).
/// </summary>
public sealed record SupersamplingImagesSettings(int Seeds, IReadOnlyList<int> Sizes);
