using System.Globalization;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// A frame estimate as one table: measures as rows, one column per pass and the total; logical
/// counts first, then each qubit model's physical figures with the per-run budget ε / R, the same
/// with ε per run, and the classical render's time on this machine with the ratio.
/// </summary>
public static class FrameTable
{
    /// <param name="frame">The priced frame.</param>
    /// <param name="machine">This machine, where the classical render was timed.</param>
    /// <param name="pricedOn">Where the Resource Estimator jobs ran when not on this machine (a cluster); null: here.</param>
    public static ReportTable For(FrameEstimate frame, string machine, string? pricedOn = null)
    {
        var cost = frame.Cost;
        var parts = cost.Passes.Append(cost.Total).ToArray();
        var settings = frame.Settings;
        var options = settings.Render;
        var table = new ReportTable($"Frame cost: {settings.Scene.Name}, {options.Width}x{options.Height}", "measure", parts.Select(p => p.Name).ToArray());
        foreach (var line in Context(frame, machine, pricedOn)) table.Context(line);
        void Row(string measure, Func<FramePart, string> value) => table.Row(measure, parts.Select(value));

        Row("Grover runs (r ≥ 1)", p => N(p.QuantumRuns));
        Row("uniform draws (r = 0, classical)", p => N(p.ClassicalDraws));
        Row("#Eval, conservative", p => N(p.Queries.QueriesConservative));
        Row("#Eval, paper", p => N(p.Queries.QueriesPaper));
        Row("logical qubits (widest run)", p => N(p.Logical.Qubits));
        Row("CCZ", p => N(p.Logical.Ccz));
        Row("CCiX", p => N(p.Logical.Ccix));
        Row("T", p => N(p.Logical.T));
        Row("rotations", p => N(p.Logical.Rotations));
        Row("measurements", p => N(p.Logical.Measurements));
        Row("classical render, this machine", p => EstimateTable.Duration(frame.ClassicalTime(p.Name).TotalNanoseconds));

        var k = cost.Qpus;
        for (var m = 0; m < cost.Models.Count; m++)
        {
            var model = cost.Models[m];
            var i = m;
            Row($"{model}: physical qubits per QPU", p => N(p.Split[i].PhysicalQubits));
            Row($"{model}: code distance, ε/R per run", p => Distance(p.Split[i]));
            Row($"{model}: runtime, 1 QPU", p => EstimateTable.Duration(p.Split[i].SequentialNanoseconds));
            if (k > 1) Row($"{model}: runtime, {k} QPUs", p => EstimateTable.Duration(p.Split[i].ParallelNanoseconds));
            Row($"{model}: runtime / classical", p => Ratio(p.Split[i].SequentialNanoseconds, frame.ClassicalTime(p.Name)));
            Row($"{model}: failure bound Σ", p => Probability(p.Split[i].FailureBound));
            Row($"{model}: code distance, ε per run", p => Distance(p.Alone[i]));
            Row($"{model}: physical qubits, ε per run", p => N(p.Alone[i].PhysicalQubits));
            Row($"{model}: runtime, 1 QPU, ε per run", p => EstimateTable.Duration(p.Alone[i].SequentialNanoseconds));
        }
        foreach (var note in Conventions(cost)) table.Note(note);
        return table;
    }

    /// <summary>What was rendered and priced, and how the budget is split.</summary>
    public static IReadOnlyList<string> Context(FrameEstimate frame, string machine, string? pricedOn = null)
    {
        var settings = frame.Settings;
        var options = settings.Render;
        var budget = frame.Cost.Budget;
        return
        [
            $"scene: {settings.Scene.Name}, {options.Width}x{options.Height}, seed {options.Seed}; render options: {options.Iterations} trace passes, {options.ShadowIterations} shadow passes, neighbours {OnOff(options.Neighbours)}, shadow neighbours {OnOff(options.ShadowNeighbours)}, stop {options.Stop.ToString().ToLowerInvariant()}, lattice {options.LatticeLevels}{(options.PlannedMiss is { } miss ? $", planned miss {miss.ToString(CultureInfo.InvariantCulture)}" : "")}; QSearch c = {settings.Search.Growth.ToString(CultureInfo.InvariantCulture)}, M sets {settings.Search.Rule}",
            $"runs recorded at the engine seam of the analytic render (the same searches as `render --engine analytic` with these options, the budget rounds one search per ray); {N(frame.Recording.Runs.Select(r => r.Shape).Distinct().Count())} distinct oracle shapes, {N(frame.Recording.Runs.Where(r => r.Iterations > 0).Select(r => r.Key).Distinct().Count())} distinct (shape, r), {N(frame.EstimatorJobs)} Resource Estimator jobs{(pricedOn is null ? "" : $" (run on {pricedOn})")}; oracle construction {settings.Construction}",
            $"error budget: frame ε = {Probability(budget.Frame)}, shared by R = {N(budget.Runs)} Grover runs: ε/R = {Probability(budget.PerRun)} per run (union bound: P(frame fails) ≤ Σ P(run fails) ≤ R · ε/R = ε)",
            $"classical: the brute-force reference render of the same frame (every primitive tested) on {machine}; wall time of the fastest of at least {FrameEstimate.ClassicalRepeats} renders, more while they took under {FrameEstimate.ClassicalTimingBudget.TotalSeconds} s together (the machine may be shared)",
        ];
    }

    public static IEnumerable<string> Conventions(FrameCost cost)
    {
        yield return "Each run is one QSearch run circuit (prepare the uniform superposition, r Grover iterations with the gate-level oracle, measure). Its logical counts: the Resource Estimator traces each distinct oracle shape (N, index, coordinate and depth bits, the comparator constants' significant bits) with r = 1 and r = 2, and r iterations count run(1) + (r − 1) · (run(2) − run(1)) (each iteration is the same circuit); each distinct set of counts is then priced by the estimator from the counts (AccountForEstimates). Runs with r = 0 sample a uniform index: no quantum processor, no price.";
        yield return "Logical counts: Σ over runs of the Resource Estimator's counts (qsharp-lang 1.32.5-dev); logical qubits: the widest run.";
        yield return "Physical qubits per QPU: the widest run's (algorithm and T factories); code distance: the smallest and largest the estimator chose over the runs, each run priced at its own (a machine fixed at the largest stays within the budget and runs a run of distance d up to d_max / d slower).";
        yield return $"Runtime, 1 QPU: Σ of the runs' runtimes, one after another. {(cost.Qpus > 1 ? $"Runtime, {cost.Qpus} QPUs: the render's engine batches one after another (a batch is one round of a pass; a ray's next search waits for the batch), each batch's runs placed longest first on the QPU free earliest. " : "")}Classical state preparation of each run's lookup table, and the host's classical work, are not in the quantum runtime.";
        yield return "Failure bound Σ: per run, logical error rate x logical qubits x logical cycles + T-state error rate x T states + the rotations' synthesis budget, from the estimator's own figures; summed over runs, a union bound on the frame failing, at most ε.";
        yield return "ε per run: every run priced with the whole frame budget to itself: the cost of a frame that may fail with probability up to R · ε.";
        yield return "Queries (#Eval): a Grover run with r ≥ 1 costs r + 1 in the conservative count (state preparation included), r in the paper's; r = 0 costs none.";
    }

    private static string Distance(FramePhysical p) => p.MinCodeDistance == p.MaxCodeDistance ? N(p.MaxCodeDistance) : $"{p.MinCodeDistance}–{p.MaxCodeDistance}";

    private static string OnOff(bool on) => on ? "on" : "off";

    public static string N(long value) => value.ToString("N0", CultureInfo.InvariantCulture);

    public static string Probability(double p) => p.ToString("0.##e+0", CultureInfo.InvariantCulture);

    /// <summary>Quantum runtime over classical wall time, e.g. "3.1e+4 x".</summary>
    public static string Ratio(double quantumNanoseconds, TimeSpan classical) =>
        classical <= TimeSpan.Zero ? "–" : $"{(quantumNanoseconds / 1e9 / classical.TotalSeconds).ToString("0.##e+0", CultureInfo.InvariantCulture)} x";
}
