using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// What `bench light-transport` measures: <paramref name="Scene"/> (an area-light scene) at <paramref name="Size"/>², each
/// shading point's set of <paramref name="AreaSamples"/> (2^k) samples, every estimator at each of <paramref name="Queries"/>
/// per point and light with seeds 1..<paramref name="Seeds"/>, errors against the exact mean of each set and against a
/// classical reference converged with <paramref name="ReferenceSamples"/> samples; with <paramref name="ImageSize"/>, images at
/// that size at each of <paramref name="ImageQueries"/> (null: none).
/// </summary>
public sealed record LightTransportSettings(Scene Scene, string SceneFile, int Size, int AreaSamples, IReadOnlyList<int> Queries, int Seeds,
    int ReferenceSamples, int? ImageSize, IReadOnlyList<int> ImageQueries);
