using QuantumRayTracing.Engines;

namespace QuantumRayTracing.Search;

/// <summary>
/// Advances many QSearch state machines together. On an engine with a fixed cost per call
/// (<see cref="IScheduleEngine"/>) each search's remaining runs are planned at once and the whole
/// batch is one engine call; otherwise the searches go in lock step, each round gathering the next
/// request of every active search into one batch, so a pass costs as many engine calls as its longest
/// search has rounds. Either way every measured index goes through <see cref="QSearch.Observe"/>.
/// </summary>
public static class QSearchDriver
{
    /// <summary>Runs every search to its end and returns the number of rounds (engine calls).</summary>
    public static int Run(IReadOnlyList<QSearch> searches, IGroverEngine engine, Action<int, int>? onRound = null)
    {
        var active = searches.Where(s => !s.IsDone).ToList();
        if (active.Count == 0) return 0;
        if (engine is IScheduleEngine scheduled)
        {
            RunSchedules(active, scheduled);
            onRound?.Invoke(1, 0);
            return 1;
        }
        var rounds = 0;
        while (active.Count > 0)
        {
            var requests = active.Select(s => s.NextRequest()).ToArray();
            var measured = engine.Measure(requests);
            if (measured.Count != requests.Length)
                throw new InvalidOperationException($"engine {engine.Name} returned {measured.Count} outcomes for {requests.Length} requests");
            for (var k = 0; k < active.Count; k++)
                active[k].Observe(measured[k]);
            rounds++;
            active.RemoveAll(s => s.IsDone);
            onRound?.Invoke(rounds, active.Count);
        }
        return rounds;
    }

    /// <summary>One call for all searches: each observes its runs' outcomes in order until it ends.</summary>
    private static void RunSchedules(List<QSearch> searches, IScheduleEngine engine)
    {
        var schedules = searches.Select(s => s.PlanRemaining()).ToArray();
        var measured = engine.MeasureSchedules(schedules);
        if (measured.Count != schedules.Length)
            throw new InvalidOperationException($"engine {engine.Name} returned {measured.Count} outcome lists for {schedules.Length} searches");
        for (var k = 0; k < searches.Count; k++)
        {
            var outcomes = measured[k];
            var used = 0;
            while (!searches[k].IsDone && used < outcomes.Length)
            {
                searches[k].NextRequest();
                searches[k].Observe(outcomes[used++]);
            }
            if (!searches[k].IsDone || used != outcomes.Length)
                throw new InvalidOperationException(
                    $"engine {engine.Name} returned {outcomes.Length} outcomes for a search of {schedules[k].Count} runs that ended after {used}");
        }
    }
}
