using QuantumRayTracing.Estimates;
using QuantumRayTracing.Intersection;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// What `estimate frame-sweep` prices: Qornell-64 and Depth Complexity 64 frames at each of <paramref name="Sizes"/>, the
/// Qornell box with each of <paramref name="Primitives"/> at <paramref name="ScalingSize"/>, and the Qornell-64 frame at
/// <paramref name="DetailedSize"/> pass by pass; each frame rendered with <paramref name="Seed"/>, its oracle built as
/// <paramref name="Construction"/>, priced on <paramref name="Models"/> within <paramref name="ErrorBudget"/>, run on
/// <paramref name="Qpus"/> processors, estimated on <paramref name="Workers"/> bridges. <paramref name="Machine"/> names
/// what the classical renders are timed on.
/// </summary>
public sealed record FrameSweepSettings(IReadOnlyList<int> Sizes, IReadOnlyList<int> Primitives, int ScalingSize, int DetailedSize, ulong Seed,
    OracleConstruction Construction, IReadOnlyList<QubitModel> Models, double ErrorBudget, int Qpus, int Workers, string Machine);
