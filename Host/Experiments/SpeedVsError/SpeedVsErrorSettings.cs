using QuantumRayTracing.Bridge;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// What `bench speed-vs-error` measures: every configuration of every engine on <paramref name="Scene"/> at
/// <paramref name="Size"/>², the full-state engine on <paramref name="Pool"/>'s bridges when given (a cluster) or local ones.
/// </summary>
public sealed record SpeedVsErrorSettings(Scene Scene, int Size, ulong Seed, int Workers, BridgePool? Pool = null);
