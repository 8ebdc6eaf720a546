using QuantumRayTracing.Engines;

namespace QuantumRayTracing.Search;

/// <summary>
/// Advances many QSearch state machines in lock step: each round gathers the next request of every
/// active search into one batch, sends it through the engine seam once, and feeds the measured
/// indices back. A pass costs as many engine calls as its longest search has rounds.
/// </summary>
public static class QSearchDriver
{
    /// <summary>Runs every search to its end and returns the number of rounds (engine calls).</summary>
    public static int Run(IReadOnlyList<QSearch> searches, IGroverEngine engine, Action<int, int>? onRound = null)
    {
        var active = searches.Where(s => !s.IsDone).ToList();
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
}
