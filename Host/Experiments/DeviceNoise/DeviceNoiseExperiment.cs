using System.Globalization;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// `bench device-noise`: the device noise model on the searches. The analytic engine's P(reading a marked index) under a device
/// model against the lookup circuit evolved exactly as a density matrix with each gate at its arity's rate and the readout applied
/// to its distribution, beside two wrong models (no readout; one rate for every gate); then renders under device models on the
/// gate-level and the lookup oracle, with and without noise-aware passes (docs/device-noise.md).
/// </summary>
public static class DeviceNoiseExperiment
{
    public const string Title = "A device noise model on the searches";

    /// <summary>A strong model, whose wrong variants miss by far: the check's rates.</summary>
    public static readonly DeviceNoiseModel Checked = new(2e-3, 3e-2, 0.05, 0.10);

    /// <summary>The renders' device models, from a near-future machine's rates to today's best.</summary>
    private static readonly (string Name, DeviceNoiseModel Device)[] Devices =
    [
        ("p1 1e-6, p2 1e-5, readout 1e-3", new DeviceNoiseModel(1e-6, 1e-5, 1e-3, 1e-3)),
        ("p1 1e-5, p2 1e-4, readout 1e-2", new DeviceNoiseModel(1e-5, 1e-4, 1e-2, 1e-2)),
        ("p1 1e-4, p2 1e-3, readout 1e-2", new DeviceNoiseModel(1e-4, 1e-3, 1e-2, 1e-2)),
    ];

    /// <summary>The check's runs: N, t, r.</summary>
    private static readonly (int Count, int Marked, int Iterations)[] Runs = [(8, 1, 1), (8, 1, 2), (8, 3, 1), (16, 1, 3), (16, 2, 2), (32, 1, 4), (64, 1, 6), (64, 4, 3)];

    public static Report Run(DeviceNoiseSettings settings, Action<string> progress)
    {
        var report = new Report(Title);
        report.Text("""
            A device model has three rates: depolarizing noise p1 (p1/3 each of X, Y, Z) after each one-qubit gate, p2 on each qubit after each
            gate on two or more qubits, none at the measurement itself, and a readout error that flips a measured 0 to 1 with P0 and a 1 to 0
            with P1 (`render` and `search` take it as `--device-noise 1q=P,2q=P` and `--readout-error P|P0,P1`). The analytic engine runs it
            through its global depolarizing approximation (a run is ideal with Φ, else it reads a uniform index), Φ from the gates' rates:
            - **gate-level oracle** (the default): the traced circuit's graded harm per gate kind, each kind at its arity's rate (H, X, Z at p1;
              CX, CZ, CCX at p2; the measurement at 0). For the harms taken as independent this is exact; the index register's channels,
              which the table keeps per Pauli and not per kind, take each Pauli's rate as the harm-weighted mean over kinds, an approximation.
            - **lookup oracle**: its circuit evolved exactly as a density matrix with each gate at its arity's rate (N a power of two up to
              64); past that, its counted locations by arity at the harmful share 2/3.

            The readout error is not in Φ: the engine flips each bit of every index it samples with its seeded generator, so renders stay
            byte-identical per seed. Noise-aware passes (`render`'s default under noise; `--ideal-plan` turns it off) plan with P(reading a marked index) = Φ (P₀ a + (1 − P₀) b) + (1 − Φ) c,
            a, b, c the readout's chances of reading a marked index from a marked one, an unmarked one and a uniform register value (on a
            typical marked set per N and t). The fullstate engine runs the lookup circuit under the device model on the simulator, each
            gate's rate set inside Q# before it and the readout flipped by the host from the seed (N a power of two; its tests check it
            against the evolved circuit); the gate engine, whose oracle is built from the QDK's arithmetic, refuses it.
            """);

        report.Heading("The model against the lookup circuit evolved exactly");
        report.Text(FormattableString.Invariant($"""
            Rates: {Checked.Description()["device model: ".Length..]}. Each row: P(reading a marked index) of the circuit evolved exactly with the readout
            applied to its distribution (*evolved*), the analytic model's (*model*), and two wrong models: without the readout error, and
            with p2 after every gate. The marked sets are the model's typical sets. Acceptance: |model − evolved| ≤ {Tolerance} (no sampling:
            both are computed); the wrong models must miss it on some row. The tests (`DeviceNoiseSearchTests`) check the same on N = 8 and 16,
            and the engine's sampled readout against the model at 40,000 runs.
            """));
        var table = new TextTable("device-model-check", ["N", "t", "r", "ideal P", "evolved", "model", "gap", "gap without readout", "gap with p2 everywhere", "within"]);
        var rates = CircuitRates.Of(Checked);
        var oneRate = rates with { OneQubit = NoiseModel.Depolarizing(Checked.TwoQubit) };
        var (worst, worstWithout, worstOneRate) = (0.0, 0.0, 0.0);
        foreach (var (count, marked, iterations) in Runs)
        {
            progress($"model check: N = {count}, t = {marked}, r = {iterations}");
            var evolved = LookupCircuitDensity.MarkedProbabilities(LookupSearchModel.TypicalSet(count, marked), iterations, rates)[iterations];
            double Gap(CircuitRates r) => DepolarizingApproximation.Default.NoisySuccess(r)(count, marked, iterations) - evolved;
            var (gap, without, one) = (Gap(rates), Gap(CircuitRates.Of(Checked.WithoutReadout())), Gap(oneRate));
            (worst, worstWithout, worstOneRate) = (Math.Max(worst, Math.Abs(gap)), Math.Max(worstWithout, Math.Abs(without)), Math.Max(worstOneRate, Math.Abs(one)));
            table.Row([N(count), N(marked), N(iterations), F(GroverProbability.OfMarked(count, marked, iterations)), F(evolved), F(evolved + gap),
                S(gap), S(without), S(one), Math.Abs(gap) <= Tolerance ? "yes" : "no"]);
        }
        report.Table(table);
        report.Text(FormattableString.Invariant($"Largest gap: model {worst:0.0000}; without readout {worstWithout:0.0000}; with p2 everywhere {worstOneRate:0.0000}."));

        report.Heading($"Rendering under device models: {settings.Scene.Name}, {settings.Size}x{settings.Size}");
        report.Text("""
            The default pipeline (`render` with no options), analytic engine, seed as below; NRMSE and #Dpix against brute force, Int/Ray
            conservative (docs/conventions.md). Wall time is the render's alone; *x noiseless* divides it by the noiseless render's.
            """);
        var options = NoisyRenderBenchmark.Defaults(settings.Size) with { Seed = settings.Seed };
        var classical = RenderMeasurement.Reference(settings.Scene, options);
        // A small render first, so the first measured row does not pay for compilation.
        RenderMeasurement.Run(settings.Scene, new EngineSetup(EngineKind.Analytic), options with { Width = 8, Height = 8 }, null);
        var renders = new TextTable("device-renders", ["device model", "oracle", "passes", "Int/Ray", "NRMSE", "#Dpix", "wall time", "x noiseless"]);
        var noiseless = RenderMeasurement.Run(settings.Scene, new EngineSetup(EngineKind.Analytic), options, classical);
        renders.Row(["none (ideal)", "", "", F2(noiseless.Result.Total.PerRayConservative), P(noiseless.Error.Nrmse), N(noiseless.Error.DifferentPixels), Seconds(noiseless.WallTime), "1.0"]);
        // Under any noise the searches run one by one, not pooled: this row costs that alone.
        var unpooled = RenderMeasurement.Run(settings.Scene, new EngineSetup(EngineKind.Analytic, new QSearchOptions(), Noise: NoiseModel.Depolarizing(Negligible)), options, classical);
        renders.Row([$"Pauli p = {Negligible:0e0} (searches unpooled)", "gate-level", "ideal miss rates", F2(unpooled.Result.Total.PerRayConservative), P(unpooled.Error.Nrmse),
            N(unpooled.Error.DifferentPixels), Seconds(unpooled.WallTime), (unpooled.WallTime / noiseless.WallTime).ToString("0.0", CultureInfo.InvariantCulture)]);
        foreach (var (name, device) in Devices)
            foreach (var oracle in new[] { NoiseOracle.GateLevel, NoiseOracle.Lookup })
                foreach (var aware in new[] { false, true })
                {
                    progress($"render: {name}, {oracle.Name()}{(aware ? ", noise-aware" : "")}");
                    var m = RenderMeasurement.Run(settings.Scene, new EngineSetup(EngineKind.Analytic, new QSearchOptions(), NoiseOracle: oracle, IdealPlan: !aware, Device: device), options, classical);
                    renders.Row([name, oracle.Name(), aware ? "noise-aware" : "ideal miss rates", F2(m.Result.Total.PerRayConservative), P(m.Error.Nrmse), N(m.Error.DifferentPixels),
                        Seconds(m.WallTime), (m.WallTime / noiseless.WallTime).ToString("0.0", CultureInfo.InvariantCulture)]);
                }
        report.Table(renders);
        report.Text(FormattableString.Invariant($"""
            Seed {settings.Seed}; brute force costs {settings.Scene.Primitives.Count} Int/Ray. The noiseless render pools its searches (docs/rendering.md); under any
            noise they run one by one, each with its own noise, and the row at p = {Negligible:0e0}, where noise changes nothing, shows what that alone costs:
            compare the device rows with it, not with the noiseless one. The noise-aware lookup rows evolve the lookup circuit for every
            marked count the planner weighs (up to N), each as deep as its schedule goes: that, not the render, is their wall time.
            """));
        return report;
    }

    /// <summary>A per-gate rate at which no run of these scenes is harmed: the render's cost without pooling alone.</summary>
    private const double Negligible = 1e-12;

    /// <summary>The largest |model − evolved| accepted.</summary>
    public const double Tolerance = 0.005;

    private static string N(long value) => value.ToString(CultureInfo.InvariantCulture);

    private static string F(double value) => value.ToString("0.0000", CultureInfo.InvariantCulture);

    private static string F2(double value) => value.ToString("0.00", CultureInfo.InvariantCulture);

    private static string S(double value) => value.ToString("+0.0000;−0.0000;0.0000", CultureInfo.InvariantCulture);

    private static string P(double value) => value.ToString("P2", CultureInfo.InvariantCulture);

    private static string Seconds(TimeSpan time) => time.TotalSeconds.ToString("0.00 s", CultureInfo.InvariantCulture);
}
