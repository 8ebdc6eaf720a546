using QuantumRayTracing.Bridge;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// What `bench fullstate-performance` measures: each of <paramref name="Scenes"/> at each of <paramref name="Sizes"/>² on the current engine,
/// and on the baseline too while pixels × primitives stay within <paramref name="BaselineLimit"/> (0: never); on
/// <paramref name="Pool"/>'s bridges when given (a cluster), else on <paramref name="Workers"/> fresh local ones per render.
/// </summary>
public sealed record FullStatePerformanceSettings(IReadOnlyList<(string Name, Scene Scene)> Scenes, IReadOnlyList<int> Sizes, long BaselineLimit, ulong Seed, int Workers, BridgePool? Pool = null);
