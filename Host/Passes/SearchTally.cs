using QuantumRayTracing.Search;

namespace QuantumRayTracing.Passes;

/// <summary>
/// How many searches of a pass ran with one QSearch schedule (null: the engine's own) and how many of
/// them found something: with the schedule's miss rate, the found ones estimate how many missed.
/// </summary>
public sealed record SearchTally(QSearchSchedule? Schedule, long Searches, long Found)
{
    /// <summary>The tallies of several passes or phases, added per schedule.</summary>
    public static IReadOnlyList<SearchTally> Join(IEnumerable<SearchTally> tallies) =>
        [.. tallies.GroupBy(t => t.Schedule).Select(g => new SearchTally(g.Key, g.Sum(t => t.Searches), g.Sum(t => t.Found)))];
}
