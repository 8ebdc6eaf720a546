using QuantumRayTracing.Bridge;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// What `bench grover-performance` measures: a Grover run at each N in <paramref name="Sizes"/>, in batches of each size in
/// <paramref name="Batches"/>, on one bridge, on <paramref name="Workers"/> bridges (or <paramref name="Pool"/>'s, a cluster's,
/// when given) and on the analytic engine; marked indices and the analytic engine seeded with <paramref name="Seed"/>.
/// </summary>
public sealed record GroverPerformanceSettings(IReadOnlyList<int> Sizes, IReadOnlyList<int> Batches, int Workers, ulong Seed, BridgePool? Pool = null);
