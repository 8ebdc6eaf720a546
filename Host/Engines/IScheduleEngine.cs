using QuantumRayTracing.Search;

namespace QuantumRayTracing.Engines;

/// <summary>
/// A Grover engine that also runs a search's remaining Grover runs in one request: the runs in order,
/// stopping after the first whose measured index is marked. QSearch then needs one engine call per
/// batch of searches instead of one per round, which matters where every call has a fixed cost.
/// </summary>
public interface IScheduleEngine : IGroverEngine
{
    /// <summary>
    /// For each schedule (a search's runs in order, all over the same marked set), the measured index of
    /// each run up to and including the first marked one; all of them when none is marked.
    /// </summary>
    IReadOnlyList<int[]> MeasureSchedules(IReadOnlyList<IReadOnlyList<GroverRequest>> schedules);
}
