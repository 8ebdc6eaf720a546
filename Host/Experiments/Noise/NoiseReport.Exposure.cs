using QuantumRayTracing.Estimates;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Reports;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Experiments;

/// <summary>The gate-level oracle's noise exposure section of docs/noise.md.</summary>
public static partial class NoiseReport
{
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
