using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// What `bench device-noise` measures: the analytic device model against the lookup circuit evolved exactly, and renders of
/// <paramref name="Scene"/> at <paramref name="Size"/>² under each device model, seed <paramref name="Seed"/>.
/// </summary>
public sealed record DeviceNoiseSettings(Scene Scene, int Size, ulong Seed);
