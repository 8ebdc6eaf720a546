using QuantumRayTracing.Bridge;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// What `bench cluster-performance` measures: a fullstate render of <paramref name="Scene"/> at <paramref name="Size"/>² on
/// <paramref name="Workers"/> local bridges and on <paramref name="Cluster"/>'s, and <paramref name="Requests"/>
/// single bridge requests timed on each; then an analytic frame of <paramref name="FrameSize"/>² by this process and by the
/// cluster's workers in tiles (0: none).
/// </summary>
public sealed record ClusterPerformanceSettings(Scene Scene, int Size, int Requests, ulong Seed, int Workers, BridgePool Cluster, int FrameSize = 0);
