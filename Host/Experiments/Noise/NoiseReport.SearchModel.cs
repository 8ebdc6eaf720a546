using QuantumRayTracing.Engines;
using QuantumRayTracing.Estimates;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Experiments;

/// <summary>The search model check's section of docs/noise.md: the model against the noisy simulator, with its negative controls.</summary>
public static partial class NoiseReport
{
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

    /// <summary>Noise locations of one Grover iteration of a search shape, from its first row with an iteration.</summary>
    private static double PerIteration(IReadOnlyList<NoiseCheckRow> rows, string oracle, int count)
    {
        var sample = rows.First(r => r.Oracle == oracle && r.Count == count && r.Iterations > 0);
        return (sample.Locations - NoiseLocations.PrepareAndMeasure(count)) / sample.Iterations;
    }
}
