using System.Diagnostics;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// Cost per Grover run on each engine at several N and batch sizes: the batch of 1 shows the
/// bridge's fixed cost per call, the large batches the amortised cost of the simulation itself.
/// Every request has one marked index and the optimal r = floor(π/4 · sqrt N).
/// </summary>
public static class GroverBenchmark
{
    public sealed record Row(int Count, int Iterations, int Batch, double FullStateOneWorkerMs, double FullStateAllWorkersMs, double AnalyticMicroseconds);

    public static int OptimalIterations(int count) => (int)Math.Floor(Math.PI / 4 * Math.Sqrt(count));

    public static GroverRequest[] Requests(int count, int batch, SeededRandom random)
    {
        var iterations = OptimalIterations(count);
        return Enumerable.Range(0, batch).Select(_ => new GroverRequest(new MarkedSet(count, [random.NextInt(count)]), iterations)).ToArray();
    }

    /// <summary>Median wall time per request over <paramref name="repeats"/> calls, after one untimed warm-up call.</summary>
    public static double MillisecondsPerRun(IGroverEngine engine, GroverRequest[] requests, int repeats)
    {
        engine.Measure(requests.Take(Math.Min(requests.Length, 10)).ToArray());
        var times = new double[repeats];
        for (var k = 0; k < repeats; k++)
        {
            var clock = Stopwatch.StartNew();
            engine.Measure(requests);
            times[k] = clock.Elapsed.TotalMilliseconds / requests.Length;
        }
        Array.Sort(times);
        return times[repeats / 2];
    }

    /// <summary>Repeats for a batch: more for small, cheap batches so a median means something.</summary>
    public static int Repeats(int batch) => batch switch { <= 1 => 9, <= 100 => 3, _ => 1 };
}
