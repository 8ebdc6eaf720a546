using System.Diagnostics;
using QuantumRayTracing.Bridge;

namespace QuantumRayTracing.Experiments;

/// <summary>What the cluster path adds to one bridge request: requests sent one at a time, timed end to end.</summary>
public static class ClusterBenchmark
{
    /// <summary>Mean milliseconds of a bridge's cheapest request (its version) on <paramref name="pool"/>, after one untimed warm-up.</summary>
    public static double RoundTripMilliseconds(BridgePool pool, int requests)
    {
        pool.ForEach([0], (_, bridge) => bridge.Version());
        var clock = Stopwatch.StartNew();
        for (var k = 0; k < requests; k++) pool.ForEach([k], (_, bridge) => bridge.Version());
        return clock.Elapsed.TotalMilliseconds / requests;
    }
}
