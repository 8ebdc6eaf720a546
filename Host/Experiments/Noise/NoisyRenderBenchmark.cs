using QuantumRayTracing.Engines;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// Rendering under noise: the default pipeline on the analytic engine at per-gate error rates, beside the
/// classical brute force (Int/Ray) and the randomized classical renderer at equal Int/Ray (NRMSE).
/// </summary>
public static class NoisyRenderBenchmark
{
    /// <summary>Per-gate error rates of the sweep, 0 the ideal machine.</summary>
    public static readonly double[] Rates = [0, 1e-7, 3e-7, 1e-6, 3e-6, 1e-5, 3e-5, 1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 1e-1];

    /// <param name="PerGate">The depolarizing rate p.</param>
    /// <param name="Measurement">The fastest of three identical renders.</param>
    /// <param name="FirstWallTime">
    /// The first of the three renders' wall time: under the lookup oracle's model it pays for evolving the circuit of each marked
    /// count the render asks at this rate, which the later renders find kept.
    /// </param>
    public sealed record Point(double PerGate, RenderMeasurement Measurement, TimeSpan FirstWallTime = default);

    /// <summary>One scene's sweep on one oracle's noise model: the quantum points, the classical reference, and the randomized renderer at 1 … k passes.</summary>
    public sealed record Sweep(string Scene, NoiseOracle Oracle, RenderMeasurement Classical, IReadOnlyList<Point> Quantum, IReadOnlyList<(int Passes, RenderMeasurement Measurement)> Randomized,
        bool NoiseAware = false)
    {
        /// <summary>The sweep's model in words and as a file-name part: the oracle, and whether the passes plan with the noise.</summary>
        public string Label => Oracle.Name() + " oracle" + (NoiseAware ? ", noise-aware render" : "");

        public string Slug => Oracle.Name() + (NoiseAware ? "-aware" : "");

        /// <summary>
        /// The randomized renderer's NRMSE at the Int/Ray <paramref name="perRay"/> (conservative): linear between the
        /// pass counts around it; null outside the range its pass counts reach.
        /// </summary>
        public double? RandomizedNrmseAt(double perRay)
        {
            var points = Randomized.Select(r => (X: r.Measurement.Result.Total.PerRayConservative, Y: r.Measurement.Error.Nrmse)).OrderBy(p => p.X).ToArray();
            for (var k = 1; k < points.Length; k++)
                if (perRay >= points[k - 1].X && perRay <= points[k].X)
                    return points[k].X == points[k - 1].X ? points[k].Y : points[k - 1].Y + (perRay - points[k - 1].X) / (points[k].X - points[k - 1].X) * (points[k].Y - points[k - 1].Y);
            return null;
        }

        /// <summary>The first rate at which <paramref name="margin"/> reaches 0 (quantum has lost), log-linearly interpolated from the rate before; null if never.</summary>
        public double? Crossing(Func<Point, double> margin)
        {
            // margin < 0: quantum still ahead; ≥ 0: it has lost.
            var sorted = Quantum.Where(p => p.PerGate > 0).OrderBy(p => p.PerGate).ToArray();
            for (var k = 0; k < sorted.Length; k++)
            {
                var m = margin(sorted[k]);
                if (double.IsNaN(m) || m < 0) continue;
                if (k == 0) return sorted[0].PerGate;
                var before = margin(sorted[k - 1]);
                if (double.IsNaN(before)) return sorted[k].PerGate;
                var f = -before / (m - before);
                return Math.Exp(Math.Log(sorted[k - 1].PerGate) + f * (Math.Log(sorted[k].PerGate) - Math.Log(sorted[k - 1].PerGate)));
            }
            return null;
        }
    }

    /// <summary>
    /// One scene's sweep over <paramref name="rates"/> on <paramref name="oracle"/>'s noise model, with <paramref name="noiseAware"/> the
    /// passes planning with the noisy runs' success (`render`'s default under noise; otherwise <c>--ideal-plan</c>).
    /// </summary>
    public static Sweep Run(string name, Scene scene, NoiseOracle oracle, int size, IReadOnlyList<double> rates, int maxRandomizedPasses, Action<string>? progress = null, bool noiseAware = false)
    {
        var options = Defaults(size);
        var classical = RenderMeasurement.Reference(scene, options);
        // One untimed render first, so the first timed one does not pay for loading and compiling the code.
        RenderMeasurement.Run(scene, new EngineSetup(EngineKind.Analytic), options, null);
        var quantum = new List<Point>();
        foreach (var p in rates)
        {
            progress?.Invoke($"{name}: analytic, {oracle.Name()} oracle{(noiseAware ? ", noise-aware" : "")}, p = {p}");
            // Same seed, same render: of three, the fastest is the cost least disturbed by other work on the machine.
            var runs = Enumerable.Range(0, 3).Select(_ => RenderMeasurement.Run(scene, new EngineSetup(EngineKind.Analytic, new QSearchOptions(), Noise: NoiseModel.Depolarizing(p), NoiseOracle: oracle, IdealPlan: !noiseAware), options, classical)).ToArray();
            quantum.Add(new Point(p, runs.MinBy(r => r.WallTime)!, runs[0].WallTime));
        }
        // The termination rule stops the randomized renderer's rays after a miss or two, so its Int/Ray would
        // level off below the quantum one: it runs the same pipeline without it, pass counts rising until its
        // Int/Ray passes every quantum point's.
        var randomized = new List<(int, RenderMeasurement)>();
        var highest = quantum.Max(q => q.Measurement.Result.Total.PerRayConservative);
        for (var passes = 1; passes <= maxRandomizedPasses; passes++)
        {
            progress?.Invoke($"{name}: randomized, {passes} passes");
            var m = RenderMeasurement.Run(scene, new EngineSetup(EngineKind.Randomized), RandomizedOptions(size, passes), classical);
            randomized.Add((passes, m));
            if (m.Result.Total.PerRayConservative > highest) break;
        }
        return new Sweep(name, oracle, classical, quantum, randomized, noiseAware);
    }

    /// <summary>
    /// The randomized renderer's pipeline: the default without the termination rule and without the accuracy budget (which would
    /// settle its rays classically), <paramref name="passes"/> passes of each kind.
    /// </summary>
    public static RenderOptions RandomizedOptions(int size, int passes) => Defaults(size) with { Stop = StopMode.Off, Iterations = passes, ShadowIterations = passes, Budget = null };

    /// <summary>The pipeline `render` runs by default, at <paramref name="size"/> square.</summary>
    public static RenderOptions Defaults(int size) => RenderDefaults.Options(size, size);

    /// <summary>
    /// A small render on the noisy gate engine (the gate-level oracle simulated) beside the analytic engine under the gate-level
    /// oracle's model, both without the accuracy budget (the simulator engines run without it) and both planning with the ideal
    /// miss rates, as the gate engine does; on <paramref name="pool"/> when given.
    /// </summary>
    public static (RenderMeasurement Analytic, RenderMeasurement Gate) Confirm(Scene scene, int size, double perGate, int workers, Bridge.BridgePool? pool = null)
    {
        var options = Defaults(size) with { Budget = null };
        var classical = RenderMeasurement.Reference(scene, options);
        var noise = NoiseModel.Depolarizing(perGate);
        return (RenderMeasurement.Run(scene, new EngineSetup(EngineKind.Analytic, new QSearchOptions(), Noise: noise, IdealPlan: true), options, classical),
            RenderMeasurement.Run(scene, new EngineSetup(EngineKind.Gate, new QSearchOptions(), workers, Noise: noise, Pool: pool), options, classical));
    }
}
