using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// What `bench optimised-tracing` measures: the paper's tables 5-8 and our default configuration at <paramref name="Size"/>²,
/// scenes by stem from <paramref name="Scene"/>, every render seeded with <paramref name="Seed"/>.
/// </summary>
public sealed record OptimisedTracingSettings(Func<string, Scene> Scene, int Size, ulong Seed, int Workers);
