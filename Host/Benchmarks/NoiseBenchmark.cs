using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Scenes.Generation;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Benchmarks;

/// <summary>
/// The measurements behind docs/noise.md: the depolarizing approximation against the noisy simulator, and
/// the paper's device experiment (fig. 15) on the noisy simulator.
/// </summary>
public static class NoiseBenchmark
{
    /// <summary>Per-gate error rates of the model check.</summary>
    public static readonly double[] CheckRates = [1e-3, 3e-3, 1e-2];

    /// <summary>
    /// The model check's runs: the lookup oracle at N = 16 and 64 with t = 1 to 3 and r near and below
    /// the optimum, and the gate-level oracle on the device experiment's ray (N = 4, r = 1) and on an
    /// 8-primitive ray (r = 1 and 2).
    /// </summary>
    public static IReadOnlyList<GroverRequest> CheckRequests()
    {
        var device = DeviceExperimentScene.Ray();
        var eight = EightPrimitiveRay();
        return
        [
            new(new MarkedSet(16, [3]), 3),
            new(new MarkedSet(16, [3, 9]), 2),
            new(new MarkedSet(64, [17]), 2),
            new(new MarkedSet(64, [17]), 6),
            new(new MarkedSet(64, [5, 17, 40]), 3),
            new(device.Table.Marked(device.Window), 1, device),
            new(eight.Table.Marked(eight.Window), 1, eight),
            new(eight.Table.Marked(eight.Window), 2, eight),
        ];
    }

    /// <summary>The first camera ray of an 8x8 image of the 8-primitive Qornell box whose full-range search marks exactly one primitive.</summary>
    public static OracleInput EightPrimitiveRay()
    {
        var scene = Scenes.SceneLoader.Parse(QornellBox.Build(8).ToJson(), "qornell-8.json");
        var geometry = new SceneGeometry(scene);
        foreach (var ray in Rays.CameraRays.For(scene.Camera, 8, 8))
        {
            var table = RayTable.Build(geometry, ray);
            if (table.Marked(table.FullRange).MarkedCount == 1) return new OracleInput(table, table.FullRange);
        }
        throw new InvalidOperationException("no camera ray of qornell-8 meets exactly one primitive");
    }

    /// <summary>One noise level of the device experiment: the measured histogram over the index register.</summary>
    public sealed record DeviceRun(double PerGate, int[] Histogram)
    {
        public int Shots => Histogram.Sum();

        /// <summary>Total variation distance from the uniform distribution: half the summed |share − 1/K|.</summary>
        public double DistanceFromUniform => TotalVariationFromUniform(Histogram);
    }

    public static double TotalVariationFromUniform(IReadOnlyList<int> histogram)
    {
        var shots = (double)histogram.Sum();
        return 0.5 * histogram.Sum(h => Math.Abs(h / shots - 1.0 / histogram.Count));
    }

    /// <summary>
    /// The paper's fig. 15 on the noisy simulator: the device experiment's ray, one gate-level Grover iteration
    /// (the optimum at N = 4, t = 1), <paramref name="shots"/> measurements per per-gate error rate.
    /// </summary>
    public static IReadOnlyList<DeviceRun> DeviceExperiment(BridgePool pool, IReadOnlyList<double> rates, int shots)
    {
        var ray = DeviceExperimentScene.Ray();
        var request = new GroverRequest(ray.Table.Marked(ray.Window), 1, ray);
        var states = 1 << SearchRegisters.For(request.Marked.Count).IndexQubits;
        var runs = new List<DeviceRun>();
        foreach (var p in rates)
        {
            using var engine = new GateEngine(pool, ownsPool: false, noise: NoiseModel.Depolarizing(p));
            var histogram = new int[states];
            foreach (var index in engine.Measure(Enumerable.Repeat(request, shots).ToArray())) histogram[index]++;
            runs.Add(new DeviceRun(p, histogram));
        }
        return runs;
    }

    /// <summary>
    /// The per-gate error at which the device experiment's distance from uniform falls to <paramref name="target"/>:
    /// log-linear interpolation between the measured rates around the crossing; null when it never crosses.
    /// </summary>
    public static double? RateAtDistance(IReadOnlyList<DeviceRun> runs, double target)
    {
        var sorted = runs.Where(r => r.PerGate > 0).OrderBy(r => r.PerGate).ToArray();
        for (var k = 1; k < sorted.Length; k++)
        {
            var (a, b) = (sorted[k - 1], sorted[k]);
            if (a.DistanceFromUniform > target && b.DistanceFromUniform <= target)
            {
                var f = (a.DistanceFromUniform - target) / (a.DistanceFromUniform - b.DistanceFromUniform);
                return Math.Exp(Math.Log(a.PerGate) + f * (Math.Log(b.PerGate) - Math.Log(a.PerGate)));
            }
        }
        return null;
    }
}
