using System.Globalization;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Estimates;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Search;
using QuantumRayTracing.Estimation;
using QuantumRayTracing.Supersampling;

namespace QuantumRayTracing.Experiments;

/// <summary>The report `qrt bench noise` writes (docs/noise.md): a section per part measured, with its tables and plots.</summary>
public static class NoiseReport
{
    /// <summary>
    /// Absolute gap allowed between the approximation and the simulator before sampling error: the
    /// approximation's own error on the supersampling circuits, measured in their check (largest |gap| − Z·σ at s = 2/3 over
    /// every case there, rounded up). The tests use the same tolerance.
    /// </summary>
    public const double ModelTolerance = 0.06;

    /// <summary>The paper's table 9: qubits, gates and depth of the oracle transpiled for ibmq_paris.</summary>
    public const int DeviceQubits = 27, DeviceGates = 18277, DeviceDepth = 11096;

    public const string Title = "Hardware noise";

    /// <summary>docs/noise.md: the parts measured, each with its tables and plots; the writer's footer names the machine and the command.</summary>
    public static Report Of(NoiseBenchResult result, NoiseBenchSettings settings)
    {
        var report = new Report(Title);
        var searchMisses = result.Check.Count(r => !r.Accepts(SearchModel.Counted, NoiseCheck.SearchTolerance, NoiseCheck.Z));
        report.Text(Lines(
            "What Pauli noise does to the quantum circuits: the noise locations of the gate-level oracle a machine would run, and which of",
            "them can harm a search; the analytic noise model of the searches checked against the noisy simulator within |gap| ≤ "
                + $"{F(NoiseCheck.SearchTolerance, "0.00")} + z·σ{(result.Check.Count == 0 ? "" : $" ({searchMisses} of {result.Check.Count} rows outside)")}, and of the",
            $"supersampling coins and QSS readouts within {F(ModelTolerance, "0.00")} + z·σ; the ray tracing paper's device experiment (sec. 8, fig. 15)",
            "reproduced on the simulator; and what noise costs a render on the gate-level oracle, beside the lookup oracle (intersections",
            "computed classically beforehand), whose circuit has far fewer noise locations."));
        Summary(report, result, settings);
        report.Text($"Measured in {F(result.Elapsed.TotalMinutes, "0.0")} min; the machine and the command that regenerates this page are named at its end.");
        if (result.Exposures.Count > 0) Exposure(report, result.Exposures, traced: settings.Parts.Contains("exposure"));
        if (settings.Parts.Contains("model")) Model(report, result.Check, settings.Shots, result.Fit);
        if (settings.Parts.Contains("supersampling")) SupersamplingCheck(report, result.Supersampling, settings.Shots);
        if (settings.Parts.Contains("device")) Device(report, result.Device, settings.DeviceShots, result.DeviceSearch!, result.DeviceOracle!, result.Machine);
        if (settings.Parts.Contains("render")) Render(report, result.Sweeps, settings.Size, result.Confirmations, settings.ConfirmSize);
        return report;
    }

    /// <summary>The page's results in a few lines before their detail: each figure is one its section below gives.</summary>
    private static void Summary(Report report, NoiseBenchResult result, NoiseBenchSettings settings)
    {
        var lines = new List<string>();
        if (settings.Parts.Contains("model") && result.Check.Count > 0)
        {
            var inside = result.Check.Count(r => r.Accepts(SearchModel.Counted, NoiseCheck.SearchTolerance, NoiseCheck.Z));
            lines.Add($"- The searches' noise model lies within {F(NoiseCheck.SearchTolerance, "0.00")} + z·σ of the noisy simulator on {inside} of {result.Check.Count} rows.");
        }
        if (settings.Parts.Contains("supersampling") && result.Supersampling.Count > 0)
            lines.Add($"- The supersampling coins' and QSS readouts' model: largest gap beyond z·σ {F(Math.Max(0, SupersamplingWorstGap(result.Supersampling)), "0.000")} "
                + $"(the tolerance is {F(ModelTolerance, "0.00")}).");
        if (settings.Parts.Contains("device") && result.Device.Count > 0)
        {
            var floor = UniformSamplingFloor(result.Device[0].Histogram.Length, settings.DeviceShots);
            var flat = NoiseBenchmark.RateAtDistance(result.Device, 2 * floor);
            var tenth = NoiseBenchmark.RateAtDistance(result.Device, 0.1);
            lines.Add($"- The paper's device experiment (fig. 15): the measured index is as flat as {settings.DeviceShots} uniform samples from "
                + $"p ≈ {(flat is { } a ? Rate(a) : "–")} per gate, within 0.1 of uniform (TVD) from p ≈ {(tenth is { } b ? Rate(b) : "–")}.");
        }
        if (settings.Parts.Contains("render") && result.Sweeps.Count > 0)
        {
            lines.Add($"- Rendering at {settings.Size}x{settings.Size}: the per-gate error p from which quantum loses (a) to brute force in Int/Ray, "
                + "(b) to the randomized renderer in NRMSE at equal Int/Ray:");
            foreach (var scene in result.Sweeps.GroupBy(s => s.Scene))
                lines.Add($"  {scene.Key}: " + string.Join("; ", scene.Select(sweep =>
                {
                    var (a, b) = Thresholds(sweep);
                    return $"{sweep.Label} (a) {a}, (b) {b}";
                })) + ".");
        }
        if (lines.Count > 0) report.Text(Lines(["**In short** (each figure from its section below):", .. lines]));
    }

    /// <summary>Where a sweep's quantum render loses: (a) to brute force in Int/Ray, (b) to the randomized renderer at equal Int/Ray.</summary>
    private static (string A, string B) Thresholds(NoisyRenderBenchmark.Sweep sweep)
    {
        var classicalPerRay = sweep.Classical.Result.Total.PerRayConservative;
        var a = sweep.Crossing(q => q.Measurement.Result.Total.PerRayConservative - classicalPerRay);
        var b = sweep.Crossing(q => sweep.RandomizedNrmseAt(q.Measurement.Result.Total.PerRayConservative) is { } r ? q.Measurement.Error.Nrmse - r : double.NaN);
        var highest = Rate(sweep.Quantum.Max(q => q.PerGate));
        return (a is { } x ? Rate(x) : $"none up to {highest}", b is { } y ? Rate(y) : $"none up to {highest}");
    }

    /// <summary>The supersampling check's largest gap beyond z·σ (negative when every row is inside z·σ).</summary>
    private static double SupersamplingWorstGap(IReadOnlyList<SupersamplingCheckRow> rows) =>
        rows.Max(r => Math.Abs(r.Observed - r.Predicted(DepolarizingApproximation.Default)) - NoiseCheck.Z * r.StandardError(DepolarizingApproximation.Default));

    // One paragraph of several source lines, kept as the lines of the Markdown.
    private static string Lines(params string[] lines) => string.Join('\n', lines);

    private static string F(double value, string format) => value.ToString(format, CultureInfo.InvariantCulture);

    private static string I(long value) => value.ToString(CultureInfo.InvariantCulture);

    private static string Rate(double p) => p == 0 ? "0" : p.ToString("0.#e0", CultureInfo.InvariantCulture);

    /// <summary>The wrong variants of the search model the check must reject, with their names in the tables.</summary>
    public static readonly (SearchModel Model, string Name)[] NegativeControls =
    [
        (SearchModel.Ideal, "ideal formula"),
        (SearchModel.ShareOne, "s = 1"),
        (SearchModel.ShareThird, "s = 1/3"),
        (SearchModel.ShareTwoThirds, "s = 2/3"),
        (SearchModel.WithoutPreparation, "without F₀"),
        (SearchModel.Ungraded, "ungraded count"),
    ];

    public static void Model(Report report, IReadOnlyList<NoiseCheckRow> rows, int shots, IReadOnlyList<NoiseCheckRow>? fit = null)
    {
        const SearchModel model = SearchModel.Counted;
        var (tolerance, z) = (NoiseCheck.SearchTolerance, NoiseCheck.Z);
        report.Heading("The analytic noise model against the noisy simulator");
        report.Text(Lines(
            "**Noise model.** The QDK's noisy simulator (`runWithNoise`): after every gate and before every measurement, on each",
            "qubit the operation touches, a Pauli X, Y or Z with probability p/3 each (depolarizing Pauli noise, `--noise p`)."));
        report.Text(Lines(
            "**The approximation** (`DepolarizingApproximation`, used by `--engine analytic --noise p`): with probability Φ a Grover run",
            "is the ideal one, otherwise it reads a uniform index of its n-qubit register:",
            "P(marked) = Φ · sin²((2r+1)θ) + (1 − Φ) · t / 2^n, with Φ = F₀ · F^r: F per Grover iteration, F₀ for the preparation and",
            "the measurement. A noise location is one qubit of one operation (a CCX is 3, a measurement 1).",
            "- Gate-level oracle (the default, `--noise-oracle gate-level`): each error's effect is found location by location in the extracted",
            $"  circuit with r_t = {GateLevelExposure.MaxTracedIterations} iterations (the counting rule and its grading below; r_t = 1 where the ray's optimal count is 1, as N = 4",
            "  with one marked: a run past its optimum reads no better than uniform and its harm is undefined), and the iterations' errors act as",
            "  channels on the index register (below); Φ is the share of the ideal run's excess over t / 2^n they keep, (P − t/2^n) / (P₀ − t/2^n),",
            "  P simulated with them. F₀ = Π over the preparation's H and the final measurement's locations and Paulis P of (1 − p_P)^h, h the graded harm.",
            $"  One number is fitted: an error whose effect the grading cannot follow costs {F(SearchChannels.FittedWholeHarm, "0.00")} of a whole harm (the fit below).",
            "- Lookup oracle (`--noise-oracle lookup`; intersections computed classically beforehand, their cost left out): no share s is",
            "  counted. Its circuit is small (n index qubits and the n − 2 auxiliaries of the Toffoli ladder, 10 qubits at N = 64), so it is",
            "  evolved exactly as a density matrix (`LookupCircuitDensity`): every gate of `MeasureGroverSearch` in order, each followed by",
            "  the Pauli channel on every qubit it touches, the measurement's X or Y flipping the read bit; P(marked) read after every",
            "  iteration. Φ = (P − t/2^n) / (P₀ − t/2^n), so the analytic engine samples exactly the evolved P(marked). Which indices are marked",
            "  changes the circuit only by its X toggles; the engine evolves one typical set per N and t (drawn once with a fixed seed) and",
            "  keeps it per noise model (`LookupSearchModel`), so a render evolves each marked count once. N above 64 or not a power of two:",
            "  Φ = (1 − p)^(s · L) over the closed-form locations L (`NoiseLocations`) with s = 2/3."));
        report.Text(Lines(
            "**The lookup search under a device model** (`DeviceNoiseModel`: p1 after one-qubit gates, p2 on each qubit of a gate on two or",
            "more, a clean measurement, readout flips P0 = P(1|0) and P1 = P(0|1)). The fullstate engine runs it as `MeasureGroverBatchOnDevice`:",
            "the gates of `MeasureGroverSearch` in the same order, the simulator's Pauli rate set to each gate's own rate before it and to 0",
            "before the measurement; the host then flips each of the n measured bits by the readout error with its seeded generator, so the",
            "read indices are reproducible given the simulator's outcomes. N must be a power of two (there the preparation is one H per qubit;",
            "otherwise it holds controlled gates the standard library decomposes into gates of mixed arity). A schedule stops at its first",
            "marked read index, so under a device model schedules run run by run, one batch per round. `FullStateDeviceNoiseTests` checks",
            "that the device circuit's traced gates are the ideal circuit's and the evolution's noise locations, and, at N = 8 with",
            "p1 = 2e-3, p2 = 3e-2, P0 = 0.02, P1 = 0.06 and 10,000 runs per row, that P(read a marked index) lies within 4 binomial standard",
            "errors of `LookupCircuitDensity` evolved at the same rates (false-failure 2.5e-4 over the four rows), while the evolution without",
            "the readout error and the one with p2 after every gate each miss some row by more than that",
            "(`dotnet test Host.Tests --filter FullStateDeviceNoiseTests`; the simulator cannot be seeded, so each run's numbers differ)."));
        report.Text(Lines(
            "**Counting rule** (Quantum/noise-exposure.mjs). The circuit's state is followed classically as branches: each qubit's value as a",
            "truth table over the qubits put into superposition (the index register), X, CX and CCX acting on the tables, diagonal gates leaving them.",
            "At each location of qubit q:",
            "- every Pauli is harmless when q's next operation is a reset;",
            "- Z is harmless when q is in a computational basis state there (the same bit on every branch, so a Z only multiplies the state",
            "  by ±1), or when the Z reaches a measurement or reset through nothing but diagonal gates and control roles; otherwise harmful;",
            "- X is followed through the rest of the circuit as a flipped bit on every branch beside the error-free run: harmless when the",
            "  difference is uncomputed, ends as the same flip on every branch of a qubit nothing reads, or reaches the H of a measurement-based",
            "  uncomputation as such a flip (there it becomes a Z the measurement does not see); harmful when it changes a phase on some",
            "  branches and not others, a measured value, or an index qubit at the diffusion's H;",
            "- Y is harmful when X or Z is.",
            "Every judgement errs towards harmful: the tables track the support of the state, not its amplitudes."));
        report.Text(Lines(
            "**Grading** (Quantum/noise-harm.mjs). A harmful error need not leave the register uniformly mixed. Between two diffusions every",
            "index qubit is in the computational basis and each branch carries the other qubits in basis states, so an error whose only",
            "effect is to flip the sign of some branches is that iteration's oracle with those signs flipped: a Z on a qubit holding the",
            "table f flips the branches where f is 1; an X that changes the oracle's diagonal gates on some branches and is then",
            "uncomputed flips those; a flipped outcome of a measurement-based uncomputation applies its correction wrongly; an X that",
            "reaches such a correction with the controls changed does so half the time (the outcome is random); an X that leaves",
            "a difference on some branches (garbage no later gate undoes) stops those branches interfering from that diffusion on.",
            "The index register's 2^n amplitudes are then simulated exactly with that error alone: h = (P₀ − P_e) / (P₀ − t/2^n), P₀",
            "the error-free P(marked), P_e with the error (none after the last diffusion, near none for a sign flip on a few unmarked",
            "indices, more than 1 where it unmarks the marked one and marks others). Any other harmful effect (inside a diffusion, on a",
            "superposed qubit, a measured index) keeps h = 1; negative h counts as 0. With these h the form Φ = Π (1 − p_P)^h agrees with the",
            "circuit to first order in p, but takes the harms of several errors as independent. The trace uses the ray's own marked set."));
        report.Text(Lines(
            "**Channels** (`SearchChannels`, `DephasedSearch`). Several errors in one run do not harm independently: two sign flips on the same",
            "branches cancel, and a register dephased in the last oracle section still reads the marked index the earlier iterations concentrated",
            "there (at N = 8, r = 2 a fully dephased last section leaves P(marked) = 0.45, not 1/8). So each iteration's errors act on the index",
            "register's density matrix: an error whose effect is a sign on some branches, or garbage that splits them, multiplies the coherence",
            "of each pair of branches it separates by −1 or 0, which at rate q decays that coherence by 1 − 2q or 1 − q; summed over the",
            "iteration's locations and averaged over each class of pairs (a marked and an unmarked index, two unmarked, two marked), every class",
            "decays at its own rate. The errors the grading cannot follow mix the register uniformly. Marked indices stay alike and unmarked alike,",
            "so the run keeps five numbers per iteration and is exact for these channels. The last iteration differs from the others: an X that",
            "leaves garbage on an oracle's work qubits only dephases the register when no later oracle computes on them, and is a whole harm",
            "before another; so the traced run's first r_t − 1 oracle sections give every iteration but the last, its last section the last",
            "(with the locations after the last diffusion). To first order the channels give the grading's harm at r_t (within 6 % at N = 8,",
            "asserted by `GateLevelExposureTests`) and more at r = 1, where a sign flip in the only oracle section costs what it costs in the",
            "first of two, not the average of two."));
        report.Text(Lines(
            $"**The check.** Each run measured {shots} times on the noisy full-state simulator (lookup oracle: fullstate engine; gate-level",
            "oracle: gate engine); the observed share of marked outcomes against the model. Acceptance: |observed − model| ≤ δ + z·σ with",
            $"δ = {F(tolerance, "0.00")} the approximation's stated tolerance, σ the binomial standard error at the model's probability and z = {F(z, "0.00")}",
            "(two-sided false-failure 1e-6 per comparison). The negative controls, each a wrong variant, must fall outside the same region",
            "on every row where they differ from the model by more than both regions together (bold: rejected there). Beside them, on the",
            "gate-level rows, the graded harms taken as independent (Φ = F₀ · F^r, F from the harm shared equally by the traced iterations):",
            "the model before the channels; on the lookup rows the evolution on the row's own marked set rather than the typical one the model",
            "takes (how much the set moves it). s = 2/3 is the lookup model before its circuit was evolved; on lookup rows \"without F₀\" is",
            "the evolution with a noiseless preparation and measurement, and \"ungraded count\" is s = 2/3 again. Harm-weighted L on lookup",
            "rows is the evolution's first-order harm, −ln Φ / p at p = 1e-6."));
        var check = new TextTable("model-check", ["oracle", "N", "t", "r", "p", "L", "harm-weighted L", "observed", "model", "gap", "gap/σ", "within δ + zσ",
            "independent harms (lookup: own set)", .. NegativeControls.Select(c => c.Name)]);
        // Each lookup row's evolution on its own marked set, once: the table and the misses below both read it.
        var ownSet = rows.Select(r => r.OwnSetProbability()).ToArray();
        foreach (var (r, own) in rows.Zip(ownSet))
        {
            var predicted = r.Predicted(model);
            var gap = r.Observed - predicted;
            var harm = r.Exposure is { } e ? e.Run(r.Iterations).HarmWeight
                : LookupSearchModel.Evolves(r.Count) ? LookupSearchModel.HarmWeight(r.Count, r.Marked, r.Iterations) : 2.0 / 3 * r.Locations;
            check.Row([r.Oracle, I(r.Count), I(r.Marked), I(r.Iterations), Rate(r.Noise.PerGate), F(r.Locations, "0"), F(harm, "0"), F(r.Observed, "0.000"), F(predicted, "0.000"),
                F(gap, "+0.000;-0.000;0.000"), F(gap / r.StandardError(model), "+0.0;-0.0;0.0"), r.Accepts(model, tolerance, z) ? "yes" : "**no**",
                r.Exposure is null ? (own is { } o ? $"own set: {F(o, "0.000")}" : "") : F(r.Predicted(SearchModel.IndependentHarms), "0.000"),
                .. NegativeControls.Select(c => r.Separates(c.Model, tolerance, z) && !r.Accepts(c.Model, tolerance, z) ? $"**{F(r.Predicted(c.Model), "0.000")}**" : F(r.Predicted(c.Model), "0.000"))]);
        }
        report.Table(check);
        var summary = new List<string>();
        var misses = rows.Where(r => !r.Accepts(model, tolerance, z)).ToArray();
        summary.Add(misses.Length == 0
            ? $"The model lies within δ + z·σ on all {rows.Count} rows."
            : $"The model misses on {misses.Length} of {rows.Count} rows: " + string.Join("; ", misses.Select(r =>
                $"{r.Oracle} N = {r.Count}, t = {r.Marked}, r = {r.Iterations}, p = {Rate(r.Noise.PerGate)}: {F(r.Observed - r.Predicted(model), "+0.000;-0.000")} ({F((r.Observed - r.Predicted(model)) / r.StandardError(model), "+0.0;-0.0")}σ)")) + ".");
        foreach (var (control, name) in NegativeControls)
        {
            var separated = rows.Where(r => r.Separates(control, tolerance, z)).ToArray();
            var rejected = separated.Count(r => !r.Accepts(control, tolerance, z));
            summary.Add($"- {name}: differs from the model on {separated.Length} rows, rejected on {rejected} of them.");
        }
        report.Text(Lines([.. summary]));
        LookupMisses(report, rows, ownSet, z);
        LookupHarm(report, rows);
        GateHarmReadBack(report, rows);
        WholeHarmFit(report, fit ?? [], shots);
        var series = rows.GroupBy(r => $"{r.Oracle} N={r.Count} t={r.Marked} r={r.Iterations}")
            .Select(g => (g.Key, (IReadOnlyList<(double, double)>)g.Select(r => (r.Noise.PerGate, r.Observed - r.Predicted(model))).ToArray()))
            .ToArray();
        report.Plot("model-check", NoisePlots.LogX("Observed - model P(marked), depolarizing Pauli noise p per gate", "per-gate error p", "observed - model", series, 0, "model"),
            "Gap between the noisy simulator and the depolarizing approximation against the per-gate error");
    }

    /// <summary>Where the lookup model still misses: the typical marked set, and what it does not evolve.</summary>
    private static void LookupMisses(Report report, IReadOnlyList<NoiseCheckRow> rows, IReadOnlyList<double?> ownSet, double z)
    {
        var lookup = rows.Where(r => r.Exposure is null).ToArray();
        if (lookup.Length == 0) return;
        var model = SearchModel.Counted;
        var worst = lookup.MaxBy(r => Math.Abs(r.Observed - r.Predicted(model)) - z * r.StandardError(model))!;
        var beyond = Math.Max(0, Math.Abs(worst.Observed - worst.Predicted(model)) - z * worst.StandardError(model));
        var largest = lookup.MaxBy(r => Math.Abs(r.Observed - r.Predicted(model)))!;
        var sets = rows.Zip(ownSet).Where(x => x.First.Exposure is null && x.Second is not null)
            .Select(x => (Row: x.First, Own: x.Second!.Value, Shift: x.Second!.Value - x.First.Predicted(model))).ToArray();
        var set = sets.Length == 0 ? default : sets.MaxBy(x => Math.Abs(x.Shift));
        string Name(NoiseCheckRow r) => $"N = {r.Count}, t = {r.Marked}, r = {r.Iterations}, p = {Rate(r.Noise.PerGate)}";
        report.Text(Lines(
            $"**The lookup model on these rows.** Largest |gap| {F(Math.Abs(largest.Observed - largest.Predicted(model)), "0.000")} ({Name(largest)},",
            $"{F((largest.Observed - largest.Predicted(model)) / largest.StandardError(model), "+0.0;-0.0")}σ); largest gap beyond z·σ {F(beyond, "0.000")}. Where it still misses:",
            sets.Length == 0 ? "- the marked set: no row was evolved on its own set." :
            $"- the marked set: the engine evolves one typical set per N and t, and a ray's own set differs in its X toggles; on these rows that moved P(marked) by up to {F(Math.Abs(set.Shift), "0.000")} ({Name(set.Row)}: own set {F(set.Own, "0.000")} against {F(set.Row.Predicted(model), "0.000")}), part of each row's gap;",
            $"- N above 64 (more than {LookupCircuitDensity.MaxQubits} qubits) or not a power of two: not evolved; those runs fall back to s = 2/3 over the counted locations, which this check does not cover;",
            $"- cost: the first render at each rate evolves a {LookupCircuitDensity.MaxQubits}-qubit density matrix for every marked count it asks at N = 64, so a one-shot render under this model is many times slower than a noiseless one (\"first of three\" against \"wall time\" in the render tables below; later renders in the same process find the evolutions kept)."));
    }

    /// <summary>
    /// Which errors harm the lookup circuit, from its evolution: per kind of location its count and its first-order harm-weighted
    /// count, for each lookup run of the check on its own marked set.
    /// </summary>
    private static void LookupHarm(Report report, IReadOnlyList<NoiseCheckRow> rows)
    {
        var runs = rows.Where(r => r.Exposure is null && LookupCircuitDensity.Evolves(r.Count) && r.Marked > 0)
            .GroupBy(r => (r.Count, string.Join(",", r.Request.Marked.Indices.ToArray()), r.Iterations)).Select(g => g.First().Request).ToArray();
        if (runs.Length == 0) return;
        report.Text(Lines(
            "**Which errors harm the lookup circuit.** The evolution to first order, noise on one kind of location at a time (p = 1e-6):",
            "L the kind's locations, H its harm-weighted count −ln Φ / p, H / L its harmful share. After an X toggle or inside the ladder",
            "most Paulis harm (an X there moves the index or leaves an auxiliary set, a Z on an auxiliary holding an AND flips some branches'",
            "sign), so the share is well above the 2/3 the counted model took; at the measurement only X and Y flip the read bit."));
        var table = new TextTable("lookup-harm", ["N", "t", "r", "marked", "L one-qubit", "H one-qubit", "L two- and three-qubit", "H two- and three-qubit", "L measurement", "H measurement", "H / L"]);
        foreach (var request in runs)
        {
            var kinds = LookupCircuitDensity.HarmByKind(request.Marked, request.Iterations);
            var (locations, harm) = (kinds.Sum(k => k.Locations), kinds.Sum(k => k.Harm));
            table.Row([I(request.Marked.Count), I(request.Marked.MarkedCount), I(request.Iterations), string.Join(" ", request.Marked.Indices.ToArray()),
                .. kinds.SelectMany(k => new[] { F(k.Locations, "0"), F(k.Harm, "0.0") }), F(harm / locations, "0.00")]);
        }
        report.Table(table);
    }

    /// <summary>
    /// Why the independent-harms form misses on the gate-level rows: per row, the harm-weighted locations H the observed share
    /// implies when read back through Φ = exp(−p · H) (rows whose implied Φ lies in 0.05 … 0.95, where it is well determined), beside
    /// the graded count, and how far the harm table's own standard error moves that form there.
    /// </summary>
    private static void GateHarmReadBack(Report report, IReadOnlyList<NoiseCheckRow> rows)
    {
        const SearchModel independent = SearchModel.IndependentHarms;
        var gate = rows.Where(r => r.Exposure is not null).ToArray();
        var table = new TextTable("model-check-read-back", ["N", "r", "p", "gap, independent harms", "gap/σ", "gap, channels", "graded H", "implied H ± σ", "shift at ± 1 s.e. of the harm table"]);
        var trends = new List<(int N, int R, double P, double Implied, double Model)>();
        foreach (var r in gate)
        {
            var uniform = (double)r.Marked / (1 << SearchRegisters.For(r.Count).IndexQubits);
            var ideal = GroverProbability.OfMarked(r.Request);
            var phi = (r.Observed - uniform) / (ideal - uniform);
            if (phi is < 0.05 or > 0.95) continue;
            var p = r.Noise.PerGate;
            var sigma = r.StandardError(independent) / ((ideal - uniform) * phi * p);
            var modelPhi = (r.Predicted(independent) - uniform) / (ideal - uniform);
            var shift = p * modelPhi * (ideal - uniform) * r.Iterations * (r.Exposure!.Estimate?.IterationError ?? double.NaN);
            var gap = r.Observed - r.Predicted(independent);
            table.Row(I(r.Count), I(r.Iterations), Rate(p), F(gap, "+0.000;-0.000;0.000"), F(gap / r.StandardError(independent), "+0.0;-0.0;0.0"),
                F(r.Observed - r.Predicted(SearchModel.Counted), "+0.000;-0.000;0.000"),
                F(r.Exposure.Run(r.Iterations).HarmWeight, "0"), $"{F(-Math.Log(phi) / p, "0")} ± {F(sigma, "0")}", F(shift, "0.000"));
            trends.Add((r.Count, r.Iterations, p, -Math.Log(phi) / p, r.Exposure.Run(r.Iterations).HarmWeight));
        }
        // Per circuit, the implied harm from the lowest error rate to the highest, beside the graded count.
        var byCircuit = trends.GroupBy(t => (t.N, t.R)).Where(g => g.Count() > 1).Select(g =>
        {
            var (low, high) = (g.MinBy(t => t.P), g.MaxBy(t => t.P));
            return $"N = {g.Key.N}, r = {g.Key.R}: {F(low.Implied, "0")} at p = {Rate(low.P)} to {F(high.Implied, "0")} at {Rate(high.P)} (graded {F(low.Model, "0")})";
        }).ToArray();
        if (table.Rows.Count == 0) return;
        report.Text(Lines(
            "**Why the independent harms missed.** Read back through Φ = exp(−p · H) (Φ from the observed share), each gate-level row implies",
            "the harm-weighted locations H below, beside the graded count the independent-harms form uses; the last column is how far the",
            "harm table's standard error moves that form's P(marked)."));
        report.Table(table);
        report.Text(Lines(
            "Implied H per circuit, lowest to highest p: " + string.Join("; ", byCircuit) + ".",
            "How to read them: where the implied H falls with p at one circuit, the form misses (several errors in one run do not harm",
            "independently: the channels above); where it differs from the graded count alike at every p, the first-order count misses (the",
            "equal split of a traced run's harm between its iterations, the effects the grading cannot follow: the fit below). The rows say",
            "which, within the implied H's standard error (± above), which at these shots is often as large as either effect."));
    }

    /// <summary>
    /// The fit behind <see cref="SearchChannels.FittedWholeHarm"/>, redone on this run's fit rows: the share of a whole harm an
    /// error the grading cannot follow costs, fitted on runs at error rates the model check does not use.
    /// </summary>
    private static void WholeHarmFit(Report report, IReadOnlyList<NoiseCheckRow> rows, int shots)
    {
        if (rows.Count == 0) return;
        var fitted = NoiseCheck.FitWholeHarm(rows);
        report.Text(Lines(
            "**The fitted share of a whole harm.** The grading gives h = 1 to every effect it cannot follow (inside a diffusion, on a",
            "superposed qubit, garbage a later oracle computes on), an upper bound: an X on an index qubit just after the first diffusion of",
            "two, for one, moves the marked amplitude to a neighbour and the second iteration recovers part of it (h = 0.69 at N = 8, t = 1). Their",
            $"mean harm is fitted: least squares in units of the binomial σ over the gate-level runs at N = 8 (r = 1 and 2) at p = {string.Join(" and ", NoiseBenchmark.GateFitRates.Select(Rate))},",
            "rates the check above does not use, so the check's rows are not the fit's, and the device ray's N = 4 is left to the check alone.",
            $"Built in: {F(SearchChannels.FittedWholeHarm, "0.00")} (fitted on these runs at 3200 shots each; `qrt bench noise --shots 3200 --parts model` measures them again and refits); on this run's fit rows ({shots} shots each): {F(fitted, "0.00")}."));
        var table = new TextTable("whole-harm-fit", ["N", "r", "p", "observed", "model (built-in share)", $"model at {F(fitted, "0.00")}", "model at 1 (whole harms)", "independent harms"]);
        foreach (var r in rows)
            table.Row(I(r.Count), I(r.Iterations), Rate(r.Noise.PerGate), F(r.Observed, "0.000"), F(r.Predicted(SearchModel.Counted), "0.000"),
                F(r.PredictedWithWholeHarm(fitted), "0.000"), F(r.PredictedWithWholeHarm(1), "0.000"), F(r.Predicted(SearchModel.IndependentHarms), "0.000"));
        report.Table(table);
    }

    /// <summary>The harmful share s fitted per coin or QSS shape; the direct coin's model has none to fit (it is exact).</summary>
    private static Dictionary<string, double> SupersamplingShares(IReadOnlyList<SupersamplingCheckRow> rows) =>
        rows.Where(r => r.Case.Kind != CoinKind.Direct).GroupBy(r => r.Case.Shape).ToDictionary(g => g.Key, g => NoiseCheck.FitHarmfulShare(g.ToArray()));

    /// <summary>Noise locations of one Grover iteration of a search shape, from its first row with an iteration.</summary>
    private static double PerIteration(IReadOnlyList<NoiseCheckRow> rows, string oracle, int count)
    {
        var sample = rows.First(r => r.Oracle == oracle && r.Count == count && r.Iterations > 0);
        return (sample.Locations - NoiseLocations.PrepareAndMeasure(count)) / sample.Iterations;
    }

    public static void SupersamplingCheck(Report report, IReadOnlyList<SupersamplingCheckRow> rows, int shots)
    {
        var model = DepolarizingApproximation.Default;
        report.Heading("The supersampling circuits under noise: the model against the noisy simulator");
        report.Text(Lines(
            "**The approximation** (`SupersamplingNoise`, used by `supersample --engine analytic --noise p`): the same global depolarizing",
            "form. A coin flip after m Grover operators shows a head with probability Φ · sin²((2m+1)θ) + (1 − Φ) · u, and a QSS readout",
            "is the ideal distribution mixed towards uniform over its 2^t values: Φ · P(y) + (1 − Φ) / 2^t. Φ = (1 − p)^(s · L) over the",
            "circuit's noise locations L (`CoinNoiseLocations`, closed forms checked against the circuits the QDK extracts), so",
            "Φ = F₀ · F^m with F = (1 − p)^(s · L_operator) per Grover operator; the preparation and measurement count by their own",
            "locations as F₀ (not as half an operator: for the mean coin they come to about F^(1/2) anyway). u is what a maximally mixed",
            "register reads as a head: ½ for the mean coin (head = coin qubit |1⟩) and the direct coin, 1/2^(n+1) for QCoin's shifted",
            "coin, whose head also needs its n subpixel qubits at 0. The direct coin is the QCoin paper's hardware coin (sec. 6): one",
            "qubit, √(1 − f)|0⟩ + √f|1⟩ by one Ry, a Grover operator of four gates (A Z A† Z), L = 2 + 4m. Its model is exact, with no s:",
            "on one qubit a Pauli error of total probability p (p/3 each) is the depolarizing channel ρ → (1 − 4p/3) ρ + (4p/3) I/2,",
            "which commutes with every gate, so Φ = (1 − 4p/3)^L (s = 2/3 would undercount its harm: a qubit in superposition has no",
            "harmless Pauli error, and the 4/3 counts the channel's own I/2 share)."));
        report.Text(Lines(
            $"**The check.** Each circuit run {shots} times on the noisy full-state simulator (`--engine fullstate --noise p`), with",
            "the mean coin's amplitudes √F(i) and the shifted coin's F(i) − E as the estimators make them. A coin counts heads; a QSS run",
            "counts readouts at the ideal distribution's two most likely values (y and 2^t − y). Acceptance: |observed − model| ≤ δ + z·σ,",
            $"σ the binomial standard error at the model's probability, z = {F(NoiseCheck.Z, "0.00")} (two-sided false-failure 1e-6 per comparison), δ = {F(ModelTolerance, "0.00")}",
            "the approximation's own tolerance, the same as for the searches. The ideal column is the noiseless probability, which the",
            "simulator leaves far behind."));
        var check = new TextTable("supersampling-check", ["circuit", "N", "m or t", "f", "p", "L", "ideal", "observed", "model, s = 2/3 (direct: exact)", "σ", "gap", "gap/σ", "within δ + zσ", "model, fitted s"]);
        var shapes = SupersamplingShares(rows);
        foreach (var r in rows)
        {
            var c = r.Case;
            var predicted = r.Predicted(model);
            var gap = r.Observed - predicted;
            var sigma = r.StandardError(model);
            var fitted = shapes.TryGetValue(c.Shape, out var share) ? r.Predicted(new DepolarizingApproximation(share)) : predicted;
            var mean = c.Kind == CoinKind.Shifted ? c.HeadAmplitude : c.HeadAmplitude * c.HeadAmplitude;
            check.Row(c.IsQss ? "QSS" : $"{c.Kind.ToString()!.ToLowerInvariant()} coin", I(c.Subpixels), c.IsQss ? $"t = {c.CounterBits}" : $"m = {c.Iterations}", F(mean, "0.000"),
                Rate(r.Noise.PerGate), I(c.Locations), F(r.Ideal, "0.000"), F(r.Observed, "0.000"), F(predicted, "0.000"), F(sigma, "0.000"), F(gap, "+0.000;-0.000;0.000"),
                F(gap / sigma, "+0.0;-0.0;0.0"), Math.Abs(gap) <= ModelTolerance + NoiseCheck.Z * sigma ? "yes" : "**no**", F(fitted, "0.000"));
        }
        report.Table(check);
        report.Text("(f: the shifted coin's head amplitude f − E, else the mean (1/N) Σ F(i). σ: the binomial standard error at the model's probability.)");
        var worst = SupersamplingWorstGap(rows);
        var summary = new List<string> { $"Largest gap beyond z·σ at s = 2/3: {F(Math.Max(0, worst), "0.000")} (the tolerance δ is {F(ModelTolerance, "0.00")})." };
        var direct = rows.Where(r => r.Case.Kind == CoinKind.Direct).ToArray();
        if (direct.Length > 0)
            summary.Add($"The direct coin's exact model: largest |gap|/σ {F(direct.Max(r => Math.Abs(r.Observed - r.Predicted(model)) / r.StandardError(model)), "0.0")} over its {direct.Length} rows (sampling error alone).");
        var rejected = rows.Count(r => Math.Abs(r.Observed - r.Ideal) > ModelTolerance + NoiseCheck.Z * r.StandardError(model));
        summary.Add($"The ideal (noiseless) probability falls outside the same acceptance region in {rejected} of {rows.Count} rows.");
        report.Text(Lines([.. summary]));
        report.Text(Lines(
            "**Fitted s per circuit shape** (least squares in units of σ over the shape's rows), and the fidelities it gives: F per Grover",
            "operator for a coin (Φ of a whole run for QSS) at two error rates:"));
        var fits = new TextTable("supersampling-fit", ["circuit", "fitted s", "L per operator (QSS: per run)", "F at p = 1e-3, s = 2/3", "F at p = 1e-3, fitted s", "F at p = 1e-2, fitted s"]);
        foreach (var (shape, s) in shapes)
        {
            var c = rows.First(r => r.Case.Shape == shape).Case;
            long locations = c.Kind is { } kind ? CoinNoiseLocations.GroverOperator(kind, c.Amplitudes) : c.Locations;
            var fitted = new DepolarizingApproximation(s);
            fits.Row(shape, F(s, "0.000"), I(locations), F(model.Fidelity(NoiseModel.Depolarizing(1e-3), locations), "0.000"),
                F(fitted.Fidelity(NoiseModel.Depolarizing(1e-3), locations), "0.000"), F(fitted.Fidelity(NoiseModel.Depolarizing(1e-2), locations), "0.000"));
        }
        report.Table(fits);
        var series = rows.GroupBy(r => r.Case.IsQss ? $"QSS N={r.Case.Subpixels} t={r.Case.CounterBits}" : $"{r.Case.Kind.ToString()!.ToLowerInvariant()} N={r.Case.Subpixels} m={r.Case.Iterations}")
            .Select(g => (g.Key, (IReadOnlyList<(double, double)>)g.Select(r => (r.Noise.PerGate, r.Observed - r.Predicted(model))).ToArray()))
            .ToArray();
        report.Plot("supersampling-check", NoisePlots.LogX("Observed - model (coin heads, QSS peak readouts), depolarizing Pauli noise p per gate (s = 2/3; direct coin exact)", "per-gate error p", "observed - model", series, 0, "model"),
            "Gap between the noisy simulator and the depolarizing approximation of the coins and QSS against the per-gate error");
    }

    /// <summary>Expected total variation distance from uniform of <paramref name="shots"/> samples of a truly uniform source over K cells (normal approximation).</summary>
    public static double UniformSamplingFloor(int cells, int shots) =>
        0.5 * cells * Math.Sqrt(2 / Math.PI) * Math.Sqrt((1.0 / cells) * (1 - 1.0 / cells) / shots);

    public static void Device(Report report, IReadOnlyList<NoiseBenchmark.DeviceRun> runs, int shots, CircuitCounts search, CircuitCounts oracle, string machine)
    {
        var states = runs[0].Histogram.Length;
        var floor = UniformSamplingFloor(states, shots);
        report.Heading("The ray tracing paper's device experiment (sec. 8) on the simulator under Pauli noise, beside its fig. 15");
        report.Text(Lines(
            "The paper ran the 4-primitive oracle search on ibmq_paris (27 qubits, quantum volume 32) and on a simulator, 1024 shots each, and",
            "found the device's histogram \"approach an uniform distribution over all possible states\". Ours: `DeviceExperimentScene`, four",
            "squares on the 16x16x16 grid, one per quadrant of the view at depths 6, 8, 10 and 12, and the first camera ray of an 8x8 image",
            $"that meets exactly one of them; one gate-level Grover iteration (the optimum at N = 4, t = 1) on the gate engine, {shots} shots per",
            "per-gate error rate, depolarizing Pauli noise p per gate and qubit, the index register measured."));
        report.Table(new TextTable("device-circuits", ["circuit", "qubits", "gates (QDK)", "depth (QDK)", "gates (CCX as Qiskit's 15)", "depth (CCX as Qiskit's 15)"])
            .Row("the search run (prepare, 1 iteration, measure), ours", I(search.Qubits), I(search.Native.GateCount), I(search.Native.Depth), I(search.QiskitCcx.GateCount), I(search.QiskitCcx.Depth))
            .Row("the oracle Int_r once (paper's table 9 circuit), ours", I(oracle.Qubits), I(oracle.Native.GateCount), I(oracle.Native.Depth), I(oracle.QiskitCcx.GateCount), I(oracle.QiskitCcx.Depth))
            .Row("paper's table 9, simulator", I(SweepReport.PaperQubits), "–", "–", I(SweepReport.PaperGates), I(SweepReport.PaperDepth))
            .Row("paper's table 9, ibmq_paris (transpiled)", I(DeviceQubits), "–", "–", I(DeviceGates), I(DeviceDepth)));
        var extra = search.Qubits - DeviceQubits;
        report.Text(Lines(
            "(Counted by the bridge's `circuit` summary, as `qrt estimate` does; the paper counts Qiskit's basis, closest to our right-hand",
            "columns. Our qubits are the peak in use, the standard library's auxiliaries included (docs/oracle-sweep.md). Z and CZ counts vary",
            "slightly run to run with the measurement-based uncomputation.)",
            $"Our search run uses {I(search.Qubits)} qubits, " + (extra > 0 ? $"{(extra == 1 ? "one" : I(extra))} more than ibmq_paris has ({I(DeviceQubits)})." : $"within ibmq_paris's {I(DeviceQubits)}.")));
        var histograms = new TextTable("device-histograms",
            ["p per gate", .. Enumerable.Range(0, states).Select(i => $"P(|{Convert.ToString(i, 2).PadLeft((int)Math.Log2(states), '0')}⟩)"), "TVD from uniform"]);
        foreach (var run in runs)
            histograms.Row([Rate(run.PerGate), .. run.Histogram.Select(h => F((double)h / run.Shots, "0.000")), F(run.DistanceFromUniform, "0.000")]);
        report.Table(histograms);
        // Bars, which a plot spec does not describe: drawn here and shown as an image.
        report.Image("device-histograms", NoisePlots.Histograms(runs, $"Device experiment: measured index, {shots} shots, depolarizing Pauli noise p per gate", machine),
            "Histograms of the device experiment's measured index at each per-gate error rate");
        var points = runs.Where(r => r.PerGate > 0).Select(r => (r.PerGate, r.DistanceFromUniform)).ToArray();
        report.Plot("device-distance", NoisePlots.LogX($"Device experiment: TVD from uniform, {shots} shots, depolarizing Pauli noise", "per-gate error p", "total variation distance from uniform",
            [("gate-level oracle search, N = 4", points)], floor, $"uniform source, {shots} shots"),
            "Total variation distance from uniform against the per-gate error");
        var flat = NoiseBenchmark.RateAtDistance(runs, 2 * floor);
        var tenth = NoiseBenchmark.RateAtDistance(runs, 0.1);
        var ratio = (double)DeviceGates / search.QiskitCcx.GateCount;
        report.Text(Lines(
            "**How flat was the device?** The paper gives fig. 15 as an image only and no number for it; the text we have of it (the",
            "extracted PDF) carries neither the bar heights nor a distance, only that the device's results approach a uniform distribution.",
            "We therefore do not claim to match a measured TVD. We report the per-gate error at which our histogram becomes",
            $"indistinguishable from uniform at {shots} shots (TVD at twice the sampling floor of a truly uniform source, {F(2 * floor, "0.000")}; the floor,",
            $"{F(floor, "0.000")}, is the expected TVD of {shots} uniform samples over {states} cells), and where it falls to 0.1:"));
        report.Text(Lines(
            $"- TVD ≤ {F(2 * floor, "0.000")} (as flat as {shots} uniform samples): p ≈ {(flat is { } a ? Rate(a) : "not reached in the rates measured")} per gate;",
            $"- TVD ≤ 0.1: p ≈ {(tenth is { } b ? Rate(b) : "not reached in the rates measured")} per gate;",
            $"- the search run has {search.Native.GateCount} gates and depth {search.Native.Depth} in the QDK's gates ({search.QiskitCcx.GateCount} and {search.QiskitCcx.Depth} with CCX as Qiskit's 15),",
            $"  so at those rates a run meets about p · (noise locations, {F(NoiseLocationsOf(search), "0")}) ≈ {(flat is { } c ? F(c * NoiseLocationsOf(search), "0.#") : "–")} and {(tenth is { } d ? F(d * NoiseLocationsOf(search), "0.#") : "–")} Pauli errors.",
            $"  The device ran a transpiled circuit of {DeviceGates} gates and depth {DeviceDepth} (table 9), {F(ratio, "0")} times our search's gate count in the",
            $"  same basis (CCX as Qiskit's 15): if errors grow with the gate count, the device's histogram turns flat at about 1/{F(ratio, "0")} of the",
            "  per-gate error above. (Rates interpolated log-linearly between the measured ones.)"));
    }

    /// <summary>
    /// Rendering under noise on the gate-level oracle's model and beside it the lookup oracle's, the thresholds of each, and the
    /// confirmations on the noisy gate engine.
    /// </summary>
    public static void Render(Report report, IReadOnlyList<NoisyRenderBenchmark.Sweep> sweeps, int size, IReadOnlyList<(string Scene, double PerGate, RenderMeasurement Analytic, RenderMeasurement FullState)> confirmations, int confirmSize)
    {
        report.Heading("Rendering under noise");
        var pipeline = NoisyRenderBenchmark.Defaults(size);
        report.Text(Lines(
            $"The default pipeline of `render` (neighbours, exact termination, a lattice of {pipeline.LatticeLevels} levels from the image size, agreed-miss {F(pipeline.AgreedMiss, "0.###")}, up to {pipeline.Iterations} rounds,",
            $"and the misses the accuracy budget asks of rays no lattice neighbour vouches for) at {size}x{size} on the analytic engine under",
            "the analytic model of depolarizing Pauli noise p per gate and qubit, seed 1, once for each oracle's circuit:",
            "- **gate-level oracle** (`--noise-oracle gate-level`, the default): the circuit a machine would run and `qrt estimate` prices, its harm",
            "  counted location by location (the exposure table above; scenes of the same N and coordinate bits share one traced circuit);",
            "- **lookup oracle** (`--noise-oracle lookup`): an oracle over intersection answers computed classically beforehand, which leaves out",
            "  the cost and the noise of computing them; its circuit evolved exactly as a density matrix (the model check above), once per",
            "  marked count the render asks, and kept for the process;",
            "- **gate-level, noise-aware** (`render`'s default under noise): the gate-level oracle's model, and the passes (termination rule, lattice",
            "  confirmations, accuracy budget, classical settling) plan with each run's noisy success instead of the ideal one, so a ray whose",
            "  noisy search would cost more than N classical tests is settled classically.",
            "Int/Ray in the conservative count (r + 1 per Grover run, every classical test counted); NRMSE against the classical",
            "render of the same options (RMS of 8-bit channel differences over the reference's range); #Dpix pixels whose 8-bit colour differs.",
            "QSearch verifies every candidate, so noise never makes a false hit: it lowers the success probability of each Grover run,",
            "which costs queries, and it makes the termination rule and the lattice's cheap confirmations (which assume the ideal miss",
            "rates) stop searches that would have hit, which costs pixels; planned with the noisy rates, it costs queries instead.",
            "Wall time: the fastest of three identical renders (same seed), and the first of them, which under the lookup oracle's model",
            "also evolves its circuits (the later ones find them kept, as every render after the first in one process does); vs noiseless:",
            "the fastest against the fastest p = 0 render of the same sweep."));
        var thresholds = new TextTable("thresholds", ["scene", "noise model from", "(a) loses to brute force in Int/Ray at p ≈", "(b) loses to the randomized renderer at equal Int/Ray at p ≈"]);
        foreach (var sweep in sweeps)
        {
            var classicalPerRay = sweep.Classical.Result.Total.PerRayConservative;
            var ideal = sweep.Quantum.First(q => q.PerGate == 0).Measurement;
            var (oracle, slug) = (sweep.Label, sweep.Slug);
            report.Heading($"{sweep.Scene}, {oracle}", 3);
            report.Text($"Classical brute force: Int/Ray {F(classicalPerRay, "0.00")}. Noise model: the {sweep.Oracle.Description()}"
                + (sweep.NoiseAware ? "; the passes plan with the noisy runs' success (`render`'s default under noise)." : "; the passes plan with the ideal miss rates (`--ideal-plan`)."));
            var quantum = new TextTable($"render-{sweep.Scene}-{slug}", ["p per gate", "Int/Ray", "NRMSE", "#Dpix", "randomized NRMSE at equal Int/Ray", "wall time", "first of three", "vs noiseless"]);
            foreach (var q in sweep.Quantum)
            {
                var m = q.Measurement;
                var randomized = sweep.RandomizedNrmseAt(m.Result.Total.PerRayConservative);
                quantum.Row(Rate(q.PerGate), F(m.Result.Total.PerRayConservative, "0.00"), F(m.Error.Nrmse * 100, "0.00") + " %", I(m.Error.DifferentPixels),
                    randomized is { } r ? F(r * 100, "0.00") + " %" : "outside its range", F(m.WallTime.TotalSeconds, "0.00") + " s", F(q.FirstWallTime.TotalSeconds, "0.00") + " s", F(m.WallTime / ideal.WallTime, "0.0") + "x");
            }
            report.Table(quantum);
            var a = sweep.Crossing(q => q.Measurement.Result.Total.PerRayConservative - classicalPerRay);
            var b = sweep.Crossing(q => sweep.RandomizedNrmseAt(q.Measurement.Result.Total.PerRayConservative) is { } r ? q.Measurement.Error.Nrmse - r : double.NaN);
            var highest = Rate(sweep.Quantum.Max(q => q.PerGate));
            var (aText, bText) = Thresholds(sweep);
            thresholds.Row(sweep.Scene, oracle, aText, bText);
            report.Text(Lines(
                $"With the {sweep.Oracle.Name()} oracle's noise model{(sweep.NoiseAware ? ", the passes planning with it" : "")}:",
                "- (a) quantum loses to classical brute force in Int/Ray " + (a is { } x2 ? $"at p ≈ {Rate(x2)} per gate;" : $"at no rate up to p = {highest} (its Int/Ray stays below {F(classicalPerRay, "0")});"),
                "- (b) quantum loses to the randomized renderer at equal Int/Ray in NRMSE " + (b is { } y2 ? $"at p ≈ {Rate(y2)} per gate." : $"at no rate up to p = {highest}.")));
            if (sweep.Oracle == NoiseOracle.GateLevel && !sweep.NoiseAware)
            {
                report.Text(Lines(
                    "The randomized renderer (floor(sqrt N) random primitives per ray and pass; the same pipeline without the termination rule,",
                    "which would stop its rays after a miss or two and cap its Int/Ray below the quantum one) at 1 … " + sweep.Randomized.Count + " passes; its NRMSE at the",
                    "quantum Int/Ray above is interpolated linearly between these (the same renders serve both oracles):"));
                var randomizedTable = new TextTable($"randomized-{sweep.Scene}", ["passes", "Int/Ray", "NRMSE", "#Dpix"]);
                foreach (var (passes, m) in sweep.Randomized)
                    randomizedTable.Row(I(passes), F(m.Result.Total.PerRayConservative, "0.00"), F(m.Error.Nrmse * 100, "0.00") + " %", I(m.Error.DifferentPixels));
                report.Table(randomizedTable);
            }
            report.Plot($"render-{sweep.Scene}-{slug}", NoisePlots.LogX($"{sweep.Scene}, {size}x{size}, {oracle}: NRMSE against per-gate error (analytic)", "per-gate error p", "NRMSE (%)",
                [("quantum, default pipeline", sweep.Quantum.Where(q => q.PerGate > 0).Select(q => (q.PerGate, q.Measurement.Error.Nrmse * 100)).ToArray()),
                 ("randomized at equal Int/Ray", sweep.Quantum.Where(q => q.PerGate > 0 && sweep.RandomizedNrmseAt(q.Measurement.Result.Total.PerRayConservative) is not null)
                    .Select(q => (q.PerGate, sweep.RandomizedNrmseAt(q.Measurement.Result.Total.PerRayConservative)!.Value * 100)).ToArray())]),
                $"{sweep.Scene}: NRMSE against the per-gate error, {oracle}");
            report.Plot($"int-per-ray-{sweep.Scene}-{slug}", NoisePlots.LogX($"{sweep.Scene}, {size}x{size}, {oracle}: Int/Ray against per-gate error (analytic)", "per-gate error p", "Int/Ray (conservative)",
                [("quantum, default pipeline", sweep.Quantum.Where(q => q.PerGate > 0).Select(q => (q.PerGate, q.Measurement.Result.Total.PerRayConservative)).ToArray())],
                classicalPerRay, "classical brute force"),
                $"{sweep.Scene}: Int/Ray against the per-gate error, {oracle}");
        }
        if (sweeps.Count > 0)
        {
            report.Heading("Thresholds", 3);
            report.Text($"Where quantum rendering loses, {size}x{size}, default pipeline, per oracle (log-linear between the measured rates):");
            report.Table(thresholds);
        }
        if (confirmations.Count > 0)
        {
            report.Heading($"The analytic model against the noisy gate engine, {confirmSize}x{confirmSize}", 3);
            report.Text(Lines(
                "The same pipeline without the accuracy budget (the simulator engines run without it) rendered by the noisy gate engine, which",
                "simulates the gate-level oracle's circuit under `runWithNoise` (`--engine gate --noise p`) and cannot be seeded, beside the",
                "analytic engine under the gate-level oracle's model: one render each, so differences of a few pixels are sampling."));
            var table = new TextTable("confirmations", ["scene", "p per gate", "analytic Int/Ray", "gate Int/Ray", "analytic NRMSE", "gate NRMSE", "analytic #Dpix", "gate #Dpix", "gate wall time"]);
            foreach (var c in confirmations)
                table.Row(c.Scene, Rate(c.PerGate), F(c.Analytic.Result.Total.PerRayConservative, "0.00"), F(c.FullState.Result.Total.PerRayConservative, "0.00"),
                    F(c.Analytic.Error.Nrmse * 100, "0.00") + " %", F(c.FullState.Error.Nrmse * 100, "0.00") + " %", I(c.Analytic.Error.DifferentPixels), I(c.FullState.Error.DifferentPixels),
                    F(c.FullState.WallTime.TotalSeconds, "0") + " s");
            report.Table(table);
        }
    }

    /// <summary>The gate-level oracle's noise exposure per traced circuit shape, and one shape's by gate kind.</summary>
    /// <param name="report">The page the section is added to.</param>
    /// <param name="exposures">Per shape: its key, the scenes of that shape and its exposure.</param>
    /// <param name="traced">Whether this run traced them (else they are the built-in table's, as an earlier `--parts exposure` run traced them).</param>
    public static void Exposure(Report report, IReadOnlyList<(string Key, string Scenes, GateLevelExposure Exposure)> exposures, bool traced)
    {
        if (exposures.Count == 0) return;
        report.Heading("Noise locations of the gate-level oracle");
        report.Text(Lines(
            "The QSearch run a machine would run (`MeasureGateGroverSearch`, the circuit `qrt estimate` prices), traced by the QDK for each",
            "circuit shape (N and coordinate bits) of the scenes up to N = 64, on the first camera ray of an 8x8 image that meets a",
            $"primitive; scenes of one shape share the first one's trace. Per Grover iteration (the circuit with {GateLevelExposure.MaxTracedIterations} iterations less the one with none, per iteration):",
            "L the noise locations, H the harm-weighted locations (a third of each Pauli's graded harm there, by the counting rule and grading of the model check below)",
            "with its standard error, and F = Φ per iteration at three error rates. The analytic engine reads this table (Host/Noise/gate-level-exposure.json)"
                + (traced ? ", which this run wrote." : ", reported here as built in; `qrt bench noise --parts exposure` traces it anew and rewrites it (the renders below read the built-in one).")));
        var table = new TextTable("exposure", ["shape", "scenes", "graded share", "L per iteration", "H per iteration", "± (s.e.)", "H / L", "L outside (prepare, measure)", "H outside", "F at 1e-5", "F at 1e-4", "F at 1e-3"]);
        foreach (var (key, scenes, e) in exposures)
            table.Row(key, scenes, e.Estimate is { } g ? F(g.Fraction, "0.##") : "ungraded", F(e.Iteration.Locations, "0"), F(e.Iteration.HarmWeight, "0"),
                e.Estimate is { } se ? F(se.IterationError, "0") : "", F(e.Iteration.HarmWeight / e.Iteration.Locations, "0.000"), F(e.Outside.Locations, "0"), F(e.Outside.HarmWeight, "0.0"),
                F(e.Iteration.Fidelity(NoiseModel.Depolarizing(1e-5)), "0.000"), F(e.Iteration.Fidelity(NoiseModel.Depolarizing(1e-4)), "0.000"), F(e.Iteration.Fidelity(NoiseModel.Depolarizing(1e-3)), "0.000"));
        report.Table(table);
        var spread = new TextTable("exposure-spread", ["shape", "graded share", "traces", "H per iteration, each trace", "spread of one trace (s.d.)", "s.d. / H"]);
        foreach (var (key, _, e) in exposures)
            if (e.Estimate is { } estimate)
                spread.Row(key, F(estimate.Fraction, "0.##"), I(estimate.Traces), string.Join(", ", estimate.IterationTraces.Select(v => F(v, "0"))),
                    F(estimate.IterationSpread, "0.0"), F(estimate.IterationSpread / e.Iteration.HarmWeight * 100, "0.0") + " %");
        report.Text(Lines(
            $"**The harm estimate.** Each shape's circuit with {GateLevelExposure.MaxTracedIterations} iterations is traced several times (below) and each trace graded",
            "(Quantum/noise-harm.mjs). The harm is split by location, not by a difference of traces: the preparation's H and the index register's",
            $"final measurement make H outside, everything else is shared equally by the {GateLevelExposure.MaxTracedIterations} iterations, so neither part can go negative.",
            "A trace's grading depends on its measured outcomes (the measurement-based uncomputation's corrections it holds), so the traces",
            "are averaged; the spread of one trace is their standard deviation, ± its standard error over the traces. Grading follows each",
            "error through the rest of the circuit, its time growing as the circuit's square, so above N = 16 each trace grades a random",
            "share of its locations (the graded share; outside locations always) weighted by its inverse: unbiased, its sampling spread part of",
            "the traces' spread. Before the grading the trace's operations are put in an order the tracker can read: the QDK lists each gate as",
            "early as its qubits allow, and a diffusion's H listed before the oracle's uncomputation of its copies on other qubits (which",
            "commutes with it) had the tracker call the register entangled for the rest of the circuit, every later error a whole harm.",
            "Each trace's per-iteration H, and their spread:"));
        report.Table(spread);
        var (largestKey, _, largest) = exposures.MaxBy(e => e.Exposure.Iteration.Locations);
        report.Text($"By gate kind, {largestKey}, one iteration (locations where the named Paulis harm; \"none\": no Pauli harms):");
        string[] patterns = ["XYZ", "XY", "YZ", ""];
        var kinds = new TextTable("exposure-kinds", ["gate kind", "locations", .. patterns.Select(p => p.Length == 0 ? "none" : p), "H"]);
        foreach (var kind in largest.Iteration.ByKind.Keys.OrderByDescending(largest.Iteration.LocationsOf))
        {
            var counts = largest.Iteration.ByKind[kind];
            kinds.Row([kind, F(largest.Iteration.LocationsOf(kind), "0"), .. patterns.Select(p => F(counts.GetValueOrDefault(p), "0")), F(largest.Iteration.HarmWeightOf(kind), "0")]);
        }
        report.Table(kinds);
        report.Text("(Z and CZ counts vary a little with the measurement-based uncomputation's outcomes, so a difference of two traces can hold a small negative count.)");
        var withChannels = exposures.Where(e => e.Exposure.Channels is not null).ToArray();
        if (withChannels.Length == 0) return;
        report.Text(Lines(
            "The same errors as channels on the index register (the model check below says how they are used), per iteration in units of",
            "a third of each Pauli's weight: whole harms (mixing), and the decay weight of a marked and an unmarked index's coherence (cross)",
            "and of two unmarked indices' (unmarked); every iteration but the last (inner) and the last:"));
        var channels = new TextTable("exposure-channels", ["shape", "inner: whole harms", "inner: cross", "inner: unmarked", "last: whole harms", "last: cross", "last: unmarked"]);
        foreach (var (key, _, exposure) in withChannels)
        {
            var (inner, last) = (exposure.Channels!.Inner, exposure.Channels.Last);
            string W(PauliWeights? w) => w is null ? "" : F(w.Depolarizing, "0");
            channels.Row(key, W(inner?.Full), W(inner?.Cross), W(inner?.Unmarked), W(last.Full), W(last.Cross), W(last.Unmarked));
        }
        report.Table(channels);
    }

    private static double NoiseLocationsOf(CircuitCounts counts) => NoiseLocations.FromCounts(counts.Native.Gates, counts.Native.Measurements);
}
