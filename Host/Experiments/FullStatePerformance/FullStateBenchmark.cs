using System.Diagnostics;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// Whole renders on the fullstate engine, where their time goes: bridge calls, the time spent in them,
/// and the Grover runs simulated. Two variants of the engine render the same scene back to back: the
/// current one, and the baseline it replaced (lock-step QSearch rounds, one call each, and the
/// standard library's multi-controlled Z in the oracle and the reflection).
/// </summary>
public static class FullStateBenchmark
{
    public enum Variant { Baseline, Current }

    /// <summary>
    /// One render: its rays, wall time, bridge calls and the time in them (summed over the workers), Grover runs, the
    /// fixed cost of one call measured just before, and the machine's 1-minute load average just after (NaN if unknown).
    /// </summary>
    public sealed record Row(string Scene, int Size, Variant Variant, int Workers, long Rays, TimeSpan Wall, long Calls, TimeSpan CallTime, long GroverRuns, double CallFloorMs, double LoadAverage)
    {
        public double MillisecondsPerRay => Wall.TotalMilliseconds / Rays;

        /// <summary>What the calls cost beyond their fixed floor: the simulation (and the Q# around it), summed over the workers.</summary>
        public double SimulationMs => Math.Max(0, CallTime.TotalMilliseconds - Calls * CallFloorMs);

        /// <summary>Share of the time in calls that is the fixed cost of a call (compiling the program).</summary>
        public double FloorShare => CallTime.TotalMilliseconds <= 0 ? 0 : Math.Min(1, Calls * CallFloorMs / CallTime.TotalMilliseconds);

        public double SimulationMsPerRun => GroverRuns == 0 ? 0 : SimulationMs / GroverRuns;

        /// <summary>The simulator-only floor: the Grover runs times their cost, spread over the workers, per ray.</summary>
        public double FloorMsPerRay => SimulationMs / Workers / Rays;
    }

    /// <summary>
    /// The `render` command's default pipeline at <paramref name="size"/>², seed <paramref name="seed"/>, without the accuracy
    /// budget: its classical settle would take the small images this measures off the simulator altogether.
    /// </summary>
    public static RenderOptions DefaultPipeline(int size, ulong seed) => RenderDefaults.Options(size, size, seed) with { Budget = null };

    /// <summary>
    /// The fixed cost of one call on this bridge: the median of <paramref name="repeats"/> calls that simulate one
    /// Grover run over a single index, after a warm-up call.
    /// </summary>
    public static double CallFloorMilliseconds(QSharpBridge bridge, string operation, int repeats = 9)
    {
        var expression = FullStateEngine.BatchExpression([new GroverRequest(new MarkedSet(1, [0]), 0)], operation);
        bridge.Run(expression);
        var times = new double[repeats];
        for (var k = 0; k < repeats; k++)
        {
            var clock = Stopwatch.StartNew();
            bridge.Run(expression);
            times[k] = clock.Elapsed.TotalMilliseconds;
        }
        Array.Sort(times);
        return times[repeats / 2];
    }

    /// <summary>
    /// Renders <paramref name="scene"/> with the default pipeline on <paramref name="pool"/> (a cluster's bridges) when given,
    /// else on a fresh pool of <paramref name="workers"/> local bridges.
    /// </summary>
    public static Row Run(string name, Scene scene, int size, Variant variant, int workers, ulong seed, BridgePool? pool = null)
    {
        using var fresh = pool is null ? new BridgePool(workers) : null;
        pool ??= fresh!;
        var floor = CallFloorMilliseconds(pool.Bridges[0], variant == Variant.Current ? QSharpOperations.MeasureGroverBatch : QSharpOperations.MeasureGroverBatchWithControlledZ);
        var (requests, time) = (pool.Requests, pool.RequestTime);
        var root = new SeededRandom(seed);
        var engine = variant == Variant.Current ? (IGroverEngine)new FullStateEngine(pool, ownsPool: false) : new BaselineEngine(pool);
        var clock = Stopwatch.StartNew();
        RenderResult result;
        using (var search = new QuantumHitSearch(engine, root.Fork(RandomStreams.Search), new QSearchOptions()))
            result = SceneRenderer.Render(scene, search, DefaultPipeline(size, seed));
        var wall = clock.Elapsed;
        var runs = engine is FullStateEngine current ? current.GroverRuns : ((BaselineEngine)engine).GroverRuns;
        return new Row(name, size, variant, pool.Workers, result.Total.Rays, wall, pool.Requests - requests, pool.RequestTime - time, runs, floor, LoadAverage());
    }

    /// <summary>The 1-minute load average (Linux /proc/loadavg), or NaN: what else the machine was running.</summary>
    public static double LoadAverage() => MachineLoad.OneMinute() ?? double.NaN;

    /// <summary>
    /// The fullstate engine as first built: a plain Grover engine, so QSearch advances in lock-step rounds of
    /// one call each, running <c>MeasureGroverBatchWithControlledZ</c> (the first construction of the oracle).
    /// </summary>
    private sealed class BaselineEngine(BridgePool pool) : IGroverEngine
    {
        public long GroverRuns { get; private set; }

        public string Name => "fullstate (baseline)";

        public IReadOnlyList<int> Measure(IReadOnlyList<GroverRequest> requests)
        {
            GroverRuns += requests.Count;
            return BridgeBatches.Measure(pool, requests, ChunkLimits.Count(FullStateEngine.DefaultMaxRequestsPerCall), QSharpOperations.MeasureGroverBatchWithControlledZ,
                r => FullStateEngine.BatchExpression(r, QSharpOperations.MeasureGroverBatchWithControlledZ));
        }

        public void Dispose() { }
    }
}
