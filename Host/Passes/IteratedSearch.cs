using System.Diagnostics;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Passes;

/// <summary>
/// The loop every pass shares: up to <c>iterations</c> rounds, each searching every unfinished ray
/// once through the engine seam. A ray's lookup table is built in its first round, in its compact form
/// (the rows inside their rectangles, all any window can accept: N row evaluations, a handful of rows
/// kept), and kept for later rounds; an engine that loads every row builds the full table itself. The pass decides the window of each search and
/// what an outcome means.
/// </summary>
public static class IteratedSearch
{
    /// <summary>Rays per engine batch: enough to fill the full-state engine's calls, few enough to keep tables small.</summary>
    public const int BlockSize = 4096;

    /// <param name="name">The pass's name, for metrics and progress.</param>
    /// <param name="search">The engine.</param>
    /// <param name="geometry">The scene's primitives.</param>
    /// <param name="rays">The pass's rays, one search per unfinished ray per round.</param>
    /// <param name="iterations">Most rounds (#IT).</param>
    /// <param name="window">The window of ray i's search, given its table.</param>
    /// <param name="observe">Takes ray i's outcome; returns true when the ray needs no further round.</param>
    /// <param name="progress">Told after each block.</param>
    /// <param name="afterRound">Runs after each round (neighbour gathering); returns its classical tests and the rays it changed.</param>
    /// <param name="settled">Rays the pass has finished by other means (a neighbour's occluder), skipped like finished ones; asked on all cores, so it must only read.</param>
    /// <param name="schedule">QSearch's schedule for (round, ray), or null for the engine's own.</param>
    /// <param name="ledger">Records every search, for the pass's expected wrong rays.</param>
    /// <param name="settle">Whether ray (round, ray) is settled classically this round instead: N tests, a certain answer.</param>
    /// <param name="among">The rays the first round may search, ascending (a lattice level's); null: every ray.</param>
    public static PassMetrics Run(
        string name, IHitSearch search, SceneGeometry geometry, IReadOnlyList<Ray> rays, int iterations,
        Func<int, RayTable, HitWindow> window, Func<int, RayTable, HitOutcome, bool> observe, IRenderProgress? progress,
        Func<(long Tests, long Updated)>? afterRound = null, Func<int, bool>? settled = null,
        Func<int, int, QSearchSchedule?>? schedule = null, RayLedger? ledger = null, Func<int, int, bool>? settle = null,
        int[]? among = null)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(iterations, 1);
        var clock = Stopwatch.StartNew();
        var cost = default(SearchCost);
        long tableRows = 0, updated = 0;
        long settledRays = 0;
        var round = 0;
        // This round's rays, and aligned with them the tables kept from the last round (null before the first round, or
        // when every ray finished) and whether each ray finished. A finished or settled ray stays so: each round's rays
        // are among the last round's.
        int[] active = [];
        RayTable?[]? kept = null;
        bool[] finished = [];
        for (; round < iterations; round++)
        {
            (active, kept) = round == 0 ? (Unsettled(among ?? [.. Enumerable.Range(0, rays.Count)], settled), null) : Unfinished(active, kept, finished, settled);
            if (active.Length == 0) break;
            finished = new bool[active.Length];
            RayTable?[]? keep = null;
            var settledThisRound = 0;
            // A block's tables are built while the block before it is searched and observed: they read only the rays and
            // the tables kept from the last round, and the searches and observations in between run mostly on one core.
            Task<RayTable[]> Tables(int from, int[] block) => Task.Run(() =>
            {
                var tables = new RayTable[block.Length];
                Parallel.For(0, block.Length, k => tables[k] = kept?[from + k] ?? RayTable.BuildCompact(geometry, rays[block[k]]));
                return tables;
            });
            int[] Block(int start) => active.AsSpan(start, Math.Min(BlockSize, active.Length - start)).ToArray();
            // One block's queries at a time, in one buffer for the round: an array per block is 128 KB for every block of every pass.
            var queryBuffer = new HitQuery[Math.Min(BlockSize, active.Length)];
            var nextBlock = Block(0);
            var nextTables = Tables(0, nextBlock);
            for (var start = 0; start < active.Length; start += BlockSize)
            {
                var (from, block, tables) = (start, nextBlock, nextTables.GetAwaiter().GetResult());
                if (start + BlockSize < active.Length)
                {
                    nextBlock = Block(start + BlockSize);
                    nextTables = Tables(start + BlockSize, nextBlock);
                }
                tableRows += (long)(kept is null ? block.Length : kept.AsSpan(from, block.Length).Count((RayTable?)null)) * geometry.Count;
                var queries = new ArraySegment<HitQuery>(queryBuffer, 0, block.Length);
                for (var k = 0; k < block.Length; k++) queries[k] = new HitQuery(tables[k], window(block[k], tables[k]), schedule?.Invoke(round, block[k]));
                var classically = settle is null ? [] : Enumerable.Range(0, block.Length).Where(k => settle(round, block[k])).ToArray();
                settledRays += classically.Length;
                settledThisRound += classically.Length;
                var outcomes = Outcomes(search, queries, classically);
                for (var k = 0; k < block.Length; k++)
                {
                    var outcome = outcomes[k];
                    cost += outcome.Cost;
                    ledger?.Record(block[k], queries[k].Schedule, outcome);
                    finished[from + k] = observe(block[k], tables[k], outcome);
                    if (!finished[from + k]) (keep ??= new RayTable?[active.Length])[from + k] = tables[k];
                }
                progress?.Report(name, (round + (double)(start + block.Length) / active.Length) / iterations);
            }
            kept = keep;
            // Gathering cannot improve answers settled classically: a round that settled every ray it searched skips it.
            if (afterRound is null || settledThisRound == active.Length) continue;
            var (tests, changed) = afterRound();
            cost += new SearchCost(0, 0, tests, 0);
            updated += changed;
        }
        return new PassMetrics(name, rays.Count, round, cost, tableRows, clock.Elapsed, updated) { SettledRays = settledRays };
    }

    // The first round's rays: those of <paramref name="among"/> not settled by other means, each asked once, on all cores.
    private static int[] Unsettled(int[] among, Func<int, bool>? settled)
    {
        if (settled is null || among.Length == 0) return among;
        var skip = new bool[among.Length];
        Parallel.ForEach(System.Collections.Concurrent.Partitioner.Create(0, among.Length, BlockSize * 16), range =>
        {
            for (var k = range.Item1; k < range.Item2; k++) skip[k] = settled(among[k]);
        });
        var unsettled = new int[skip.AsSpan().Count(false)];
        for (int k = 0, n = 0; n < unsettled.Length; k++)
            if (!skip[k]) unsettled[n++] = among[k];
        return unsettled;
    }

    // The next round's rays among this round's, with their kept tables.
    private static (int[] Active, RayTable?[]? Kept) Unfinished(int[] active, RayTable?[]? kept, bool[] finished, Func<int, bool>? settled)
    {
        var next = new List<int>();
        var tables = new List<RayTable?>();
        for (var k = 0; k < active.Length; k++)
        {
            if (finished[k] || settled?.Invoke(active[k]) == true) continue;
            next.Add(active[k]);
            tables.Add(kept?[k]);
        }
        return ([.. next], kept is null ? null : [.. tables]);
    }

    // The engine answers every query but the ones settled classically, which test every primitive (the classical
    // engine's search, whatever the engine: the same N tests brute force would make).
    private static IReadOnlyList<HitOutcome> Outcomes(IHitSearch search, ArraySegment<HitQuery> queries, int[] classically)
    {
        // The engine's answers as they come: a copy of a block's outcomes is 192 KB for every block of every pass.
        if (classically.Length == 0) return search.Run(queries);
        var isClassical = new bool[queries.Count];
        foreach (var k in classically) isClassical[k] = true;
        var quantum = Enumerable.Range(0, queries.Count).Where(k => !isClassical[k]).ToArray();
        var outcomes = new HitOutcome[queries.Count];
        var fromEngine = quantum.Length == 0 ? [] : search.Run([.. quantum.Select(k => queries[k])]);
        for (var j = 0; j < quantum.Length; j++) outcomes[quantum[j]] = fromEngine[j];
        var settled = Classical.Run([.. classically.Select(k => queries[k])]);
        for (var j = 0; j < classically.Length; j++) outcomes[classically[j]] = settled[j];
        return outcomes;
    }

    private static readonly ClassicalHitSearch Classical = new();
}
