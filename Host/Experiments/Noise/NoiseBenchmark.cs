using QuantumRayTracing.Reports;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Estimates;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Scenes.Generation;
using QuantumRayTracing.Search;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// The measurements behind docs/noise.md: the depolarizing approximation against the noisy simulator, and
/// the paper's device experiment (fig. 15) on the noisy simulator.
/// </summary>
public static class NoiseBenchmark
{
    /// <summary>
    /// Runs the parts <paramref name="settings"/> asks for, in order: the model check and the device experiment on
    /// one bridge pool (the cluster's when the settings give one), then the analytic renders and the fullstate confirmations.
    /// </summary>
    public static NoiseBenchResult Run(NoiseBenchSettings settings, Action<string> progress)
    {
        var clock = System.Diagnostics.Stopwatch.StartNew();
        void Say(string message) => progress($"{message} ({clock.Elapsed.TotalSeconds:0} s so far)");
        string machine;
        IReadOnlyList<NoiseCheckRow> check = [], fit = [];
        IReadOnlyList<SupersamplingCheckRow> supersampling = [];
        IReadOnlyList<DeviceRun> device = [];
        CircuitCounts? deviceSearch = null, deviceOracle = null;
        var exposures = new List<(string, string, GateLevelExposure)>();
        using (var local = settings.Pool is null ? new BridgePool(settings.Workers) : null)
        {
            var pool = settings.Pool ?? local!;
            var versions = pool.Bridges[0].Version();
            machine = MachineDescription.Describe(versions["qsharp"]?.GetValue<string>(), versions["node"]?.GetValue<string>());
            foreach (var group in (settings.ExposureScenes ?? []).GroupBy(s => GateLevelExposure.KeyOf(s.Scene)))
            {
                var (name, scene) = group.First();
                var names = string.Join(", ", group.Select(g => g.Name));
                // Without the exposure part, the built-in table the renders read is reported as it stands.
                if (!settings.Parts.Contains("exposure"))
                {
                    if (GateLevelExposureTable.Entries.TryGetValue(group.Key, out var builtIn)) exposures.Add((group.Key, names, builtIn));
                    continue;
                }
                Say($"gate-level noise exposure of {group.Key} ({name})");
                exposures.Add((group.Key, names, GateLevelExposure.Trace(pool, GateLevelExposure.RepresentativeRay(scene), $"{name}'s circuit, {group.Key}",
                    NoiseBenchSettings.HarmTraces(scene.Primitives.Count), NoiseBenchSettings.GradedFraction(scene.Primitives.Count))));
            }
            if (settings.Parts.Contains("model"))
            {
                var requests = CheckRequests();
                Say($"model check: {requests.Count} runs x {CheckRates.Length} error rates x {settings.Shots} shots");
                check = [.. NoiseCheck.Measure(pool, requests.Where(r => r.Oracle is null).ToArray(), CheckRates.Select(p => NoiseModel.Depolarizing(p)).ToArray(), settings.Shots),
                    .. NoiseCheck.Measure(pool, requests.Where(r => r.Oracle is not null).ToArray(), GateCheckRates.Select(p => NoiseModel.Depolarizing(p)).ToArray(), settings.Shots)];
                Say($"whole-harm fit: {FitRequests().Count} runs x {GateFitRates.Length} error rates x {settings.Shots} shots");
                fit = NoiseCheck.Measure(pool, FitRequests(), GateFitRates.Select(p => NoiseModel.Depolarizing(p)).ToArray(), settings.Shots);
            }
            if (settings.Parts.Contains("supersampling"))
            {
                Say($"supersampling model check: {SupersamplingCheckCases().Count} circuits x {SupersamplingCheckRates.Length} error rates x {settings.Shots} shots");
                supersampling = SupersamplingNoiseCheck.Measure(pool, SupersamplingCheckCases(), SupersamplingCheckRates.Select(p => NoiseModel.Depolarizing(p)).ToArray(), settings.Shots);
            }
            if (settings.Parts.Contains("device"))
            {
                Say($"device experiment: {NoiseBenchSettings.DeviceRates.Length} error rates x {settings.DeviceShots} shots");
                device = DeviceExperiment(pool, NoiseBenchSettings.DeviceRates, settings.DeviceShots);
                var argument = GateEngine.OracleArgument(DeviceExperimentScene.Ray());
                deviceSearch = Trace(pool, $"{QSharpOperations.MeasureGateGroverSearch}({argument}, 1)");
                deviceOracle = Trace(pool, $"{QSharpOperations.ApplyIntersectionOracleOnNewRegisters}({argument})");
            }
        }
        var sweeps = new List<NoisyRenderBenchmark.Sweep>();
        var confirmations = new List<(string, double, RenderMeasurement, RenderMeasurement)>();
        if (settings.Parts.Contains("render"))
        {
            foreach (var (name, scene) in settings.Scenes)
                foreach (var (oracle, aware) in new[] { (NoiseOracle.GateLevel, false), (NoiseOracle.GateLevel, true), (NoiseOracle.Lookup, false) })
                    sweeps.Add(NoisyRenderBenchmark.Run(name, scene, oracle, settings.Size, NoisyRenderBenchmark.Rates, 16, Say, aware));
            if (settings.ConfirmSize > 0 && settings.ConfirmScene is var (small, smallScene))
            {
                foreach (var p in settings.ConfirmRates)
                {
                    Say($"{small} at {settings.ConfirmSize}x{settings.ConfirmSize}: analytic and gate engine, p = {p}");
                    var (analytic, gate) = NoisyRenderBenchmark.Confirm(smallScene, settings.ConfirmSize, p, settings.Workers, settings.Pool);
                    confirmations.Add((small, p, analytic, gate));
                }
            }
        }
        return new NoiseBenchResult(machine, clock.Elapsed, check, supersampling, device, deviceSearch, deviceOracle, sweeps, confirmations, exposures, fit);
    }

    /// <summary>Gate counts and depth of a Q# call's circuit, as the bridge summarises it.</summary>
    private static CircuitCounts Trace(BridgePool pool, string expression)
    {
        CircuitCounts? counts = null;
        pool.ForEach([expression], (e, bridge) => counts = CircuitCounts.Parse(bridge.Circuit(e)));
        return counts!;
    }

    /// <summary>Per-gate error rates of the model check on the lookup oracle.</summary>
    public static readonly double[] CheckRates = [1e-3, 3e-3, 1e-2];

    /// <summary>Per-gate error rates of the model check on the gate-level oracle, whose runs are uniform past 3e-3.</summary>
    public static readonly double[] GateCheckRates = [1e-4, 3e-4, 1e-3, 3e-3];

    /// <summary>
    /// The model check's runs: the lookup oracle at N = 8, 16 and 64 with t = 1 to 3 and r near and below
    /// the optimum, and the gate-level oracle on the device experiment's ray (N = 4, r = 1) and on an
    /// 8-primitive ray (r = 1 and 2).
    /// </summary>
    public static IReadOnlyList<GroverRequest> CheckRequests()
    {
        var device = DeviceExperimentScene.Ray();
        var eight = EightPrimitiveRay();
        return
        [
            new(new MarkedSet(8, [5]), 2),
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

    /// <summary>
    /// Per-gate error rates at which the gate-level runs the fit of <see cref="SearchChannels.FittedWholeHarm"/> reads are measured:
    /// between the model check's, none of them, so the check's rows are not the fit's.
    /// </summary>
    public static readonly double[] GateFitRates = [6e-4, 2e-3];

    /// <summary>The runs the whole-harm share is fitted on: the 8-primitive ray at r = 1 and 2 (the device ray's N = 4 is left to the check).</summary>
    public static IReadOnlyList<GroverRequest> FitRequests()
    {
        var eight = EightPrimitiveRay();
        return [new(eight.Table.Marked(eight.Window), 1, eight), new(eight.Table.Marked(eight.Window), 2, eight)];
    }

    /// <summary>Per-gate error rates of the supersampling model check: the coins' and QSS's fidelities span about 0.99 to 0 over them.</summary>
    public static readonly double[] SupersamplingCheckRates = [3e-4, 1e-3, 3e-3, 1e-2];

    /// <summary>
    /// The supersampling model check's circuits: the mean and the shifted (QCoin) coin over 4 subpixels at m = 0, 1, 2,
    /// the mean coin over 16 subpixels (4x4, the default supersampling tile) at m = 1, the direct single-qubit coin (the
    /// QCoin paper's hardware coin) at f = 0.1 and m = 4 and 16, and QSS readouts over 4 subpixels with 3 counter bits and
    /// over 16 with 2. Means away from ½, where the amplified head probability sits far from the ½ noise pulls it to (the mean
    /// coin's 0.0955 = sin²(π/10) gives a certain head at m = 2).
    /// </summary>
    public static IReadOnlyList<SupersamplingCheckCase> SupersamplingCheckCases()
    {
        var mean = CoinValues.MeanCoin([0.05, 0.2, 0.1, 0.032]);
        var shifted = CoinValues.Shifted([0.3, 0.5, 0.2, 0.6], 0.2);
        var tile = CoinValues.MeanCoin(Enumerable.Range(0, 16).Select(i => (i * 7 % 16) / 20.0).ToArray());
        double[] direct = [Math.Sqrt(0.1)];
        return
        [
            .. Enumerable.Range(0, 3).Select(m => SupersamplingCheckCase.Coin(CoinKind.Mean, mean, m)),
            .. Enumerable.Range(0, 3).Select(m => SupersamplingCheckCase.Coin(CoinKind.Shifted, shifted, m)),
            SupersamplingCheckCase.Coin(CoinKind.Mean, tile, 1),
            SupersamplingCheckCase.Coin(CoinKind.Direct, direct, 4),
            SupersamplingCheckCase.Coin(CoinKind.Direct, direct, 16),
            SupersamplingCheckCase.Qss(mean, 3),
            SupersamplingCheckCase.Qss(tile, 2),
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
