using System.Diagnostics;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Engines;

namespace QuantumRayTracing.Search;

/// <summary>
/// One `search`: many QSearch instances over one marked set, each with its own random stream forked from the
/// seed, advanced in lock step on one Grover engine; what they found and what they cost, in one record.
/// </summary>
public static class SearchRun
{
    /// <param name="settings">The run.</param>
    /// <param name="onRound">Called after each round with the round number and the searches still active.</param>
    public static SearchRunResult Run(SearchRunSettings settings, Action<int, int>? onRound = null)
    {
        var root = new SeededRandom(settings.Seed);
        var (marked, schedule) = (settings.MarkedSet, settings.Schedule);
        var searches = Enumerable.Range(0, settings.Searches)
            .Select(k => new QSearch(marked, schedule, root.Fork(RandomStreams.FirstSearch + (ulong)k)))
            .ToArray();
        var clock = Stopwatch.StartNew();
        int rounds;
        using (var engine = EngineFactory.Create(settings.Engine, new SeededRandom(settings.Seed)))
            rounds = QSearchDriver.Run(searches, engine, onRound);
        clock.Stop();

        var figures = new SearchFigures(settings.Count, marked.Indices.ToArray(), schedule.Bounds.ToArray(), settings.Registers, searches.Length,
            searches.Count(s => s.Found is not null), searches.Aggregate(default(SearchCost), (sum, s) => sum + s.Cost), rounds, clock.Elapsed);
        return new SearchRunResult(figures, EngineFactory.Place(settings.Engine.Kind, settings.Engine.Pool, settings.Engine.Workers));
    }
}
