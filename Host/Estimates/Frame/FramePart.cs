using QuantumRayTracing.Search;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// One pass of a frame, or the whole frame: its Grover runs, their oracle queries (both counts), the
/// sum of their logical operations (qubits: the widest run), and their physical figures on each model
/// with the per-run budget (<see cref="Split"/>) and with the frame budget per run (<see cref="Alone"/>).
/// Runs with r = 0 draw a uniform index, which needs no quantum processor: they are counted in
/// <see cref="ClassicalDraws"/> and priced at nothing.
/// </summary>
public sealed record FramePart(
    string Name,
    long QuantumRuns,
    long ClassicalDraws,
    SearchCost Queries,
    LogicalCounts Logical,
    IReadOnlyList<FramePhysical> Split,
    IReadOnlyList<FramePhysical> Alone);
