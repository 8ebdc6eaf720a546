using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// What `bench lights` measures: renders at <paramref name="Size"/>², errors against a classical reference converged with
/// <paramref name="ReferenceSamples"/> samples per point, and with <paramref name="ImageSize"/> images of each case at that
/// size (null: none); scenes by stem from <paramref name="Scene"/>.
/// </summary>
public sealed record LightsSettings(Func<string, Scene> Scene, int Size, int? ImageSize, int ReferenceSamples, ulong Seed);
