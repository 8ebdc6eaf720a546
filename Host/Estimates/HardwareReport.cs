using System.Globalization;
using System.Text;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// docs/hardware.md: what whole frames cost on fault-tolerant machines. The scenes at several image
/// sizes on every model, the Qornell box against N at one size (with a plot), the cost per pixel
/// against the image size, one frame per pass, and the paper's hardware run for context.
/// </summary>
/// <param name="Scenes">Frames of the named scenes, in order: (scene label, size, estimate).</param>
/// <param name="ByPrimitives">Frames of the Qornell box with N primitives at <paramref name="ScalingSize"/>, ascending N.</param>
/// <param name="ScalingSize">Image side of the frames against N.</param>
/// <param name="Detailed">The frame shown pass by pass.</param>
/// <param name="PaperDevice">One QSearch run of the paper's 4-primitive oracle on every model (budget 10⁻³), for context.</param>
public sealed record HardwareReport(
    IReadOnlyList<(string Scene, int Size, FrameEstimate Frame)> Scenes,
    IReadOnlyList<(int Primitives, FrameEstimate Frame)> ByPrimitives,
    int ScalingSize,
    FrameEstimate Detailed,
    CircuitEstimate PaperDevice)
{
    /// <summary>The report's Markdown; <paramref name="plot"/> is the runtime plot's file name beside it, or null.</summary>
    public string Markdown(string command, string machine, string? plot)
    {
        var first = Detailed;
        var models = first.Cost.Models;
        var qpus = first.Cost.Qpus;
        var budget = first.Settings.ErrorBudget;
        var text = new StringBuilder();
        text.AppendLine("# What a frame costs on a fault-tolerant machine");
        text.AppendLine();
        text.AppendLine("`qrt estimate` prices one ray's circuits; a frame is about 10^5 Grover runs of many lengths over primary, specular and shadow");
        text.AppendLine("rays. `qrt estimate --frame` renders a frame with the analytic engine (the same searches as `render --engine analytic` with the");
        text.AppendLine("same options and seed), records every Grover run at the engine seam (pass, engine batch, N, r, oracle shape), prices each run's");
        text.AppendLine("gate-level circuit with the Microsoft Resource Estimator, and sums. This report applies it to the paper's scenes.");
        text.AppendLine();
        text.AppendLine($"Regenerate: `{command}`. Machine: {machine}. The machine was shared with other work while it ran: a classical wall time is the fastest of at least {FrameEstimate.ClassicalRepeats} renders (more while they took under {FrameEstimate.ClassicalTimingBudget.TotalSeconds} s together), and still noisy.");
        text.AppendLine();
        var headline = Detailed.Cost.Total;
        var options = Detailed.Settings.Render;
        text.AppendLine($"In short: a {options.Width}x{options.Height} frame of the {Detailed.Settings.Scene.Name} makes {N(headline.QuantumRuns)} Grover runs ({N(headline.Logical.Ccz)} CCZ in all).");
        for (var m = 0; m < models.Count; m++)
        {
            var p = headline.Split[m];
            text.AppendLine($"On {models[m]} it needs {N(p.PhysicalQubits)} physical qubits at code distance up to {p.MaxCodeDistance} and {Duration(p.SequentialNanoseconds)} on one QPU ({Duration(p.ParallelNanoseconds)} on {qpus}),");
            text.AppendLine($"{FrameTable.Ratio(p.SequentialNanoseconds, Detailed.ClassicalTime(headline.Name))} the classical render's {Duration(Detailed.ClassicalTime(headline.Name).TotalNanoseconds)} here.");
        }
        text.AppendLine();
        text.AppendLine("## How a frame is priced");
        text.AppendLine();
        text.AppendLine("- A Grover run with r ≥ 1 is one QSearch run circuit: prepare the uniform superposition over the N primitives, r Grover iterations with the");
        text.AppendLine($"  gate-level intersection oracle ({first.Settings.Construction} construction), measure. Runs with r = 0 sample a uniform index, which needs no quantum processor.");
        text.AppendLine("- Its cost depends only on the oracle's shape (N, index, coordinate and depth bits, and how many bits each comparator with a constant");
        text.AppendLine("  compares) and r. The estimator traces each shape's circuit with r = 1 and r = 2; r iterations have exactly run(1) + (r − 1) · (run(2) − run(1))");
        text.AppendLine("  logical operations; each distinct set of counts is priced by the estimator from the counts (`AccountForEstimates`). A test renders a 4x4");
        text.AppendLine("  frame and checks every figure against each run's own circuit estimated on its own.");
        text.AppendLine($"- Error budget: the frame may fail with probability at most ε = {FrameTable.Probability(budget)}. It fails only if one of its R runs fails, so giving");
        text.AppendLine("  each run ε / R keeps it within ε (union bound); each run's failure bound (logical error rate x logical qubits x cycles + T-state error");
        text.AppendLine("  rate x T states, from the estimator's own figures) is summed and shown. \"ε per run\" prices every run with the whole ε instead: the");
        text.AppendLine("  cheaper machine of a frame that may fail R times as often.");
        text.AppendLine($"- Physical qubits: the widest run's, algorithm and T factories (what each processor holds). Runtime, 1 QPU: the runs one after another.");
        text.AppendLine($"  Runtime, {qpus} QPUs: the render's engine batches (a round of a pass) one after another, each batch's runs placed longest first on the");
        text.AppendLine("  processor free earliest. Code distance: the range the estimator chose over the runs; each run is priced at its own. A machine");
        text.AppendLine("  fixed at the largest stays within the budget and runs a run of distance d up to d_max / d slower (a logical cycle lasts in");
        text.AppendLine("  proportion to the distance).");
        text.AppendLine("- Classical: the brute-force reference render of the same frame (every primitive tested, no pipeline tricks) on this machine, whole render");
        text.AppendLine("  wall time. The ratio is quantum runtime on one QPU over it. Lookup-table preparation and the host's classical work are not in the quantum runtime.");
        text.AppendLine("- Queries: a run with r ≥ 1 is r + 1 oracle queries in the conservative count, r in the paper's; both are the render's own #Eval.");
        text.AppendLine($"- Render options: the defaults of `render` (neighbours, shadow neighbours, exact termination, lattice), seed {first.Settings.Render.Seed}.");
        text.AppendLine();

        text.AppendLine("## The paper's scenes");
        text.AppendLine();
        text.AppendLine("| scene | size | Grover runs | per pixel | #Eval, conservative | CCZ | measurements | logical qubits | classical render |");
        text.AppendLine("|---|---|---:|---:|---:|---:|---:|---:|---:|");
        foreach (var (scene, size, frame) in Scenes)
        {
            var t = frame.Cost.Total;
            text.AppendLine($"| {scene} | {size}x{size} | {N(t.QuantumRuns)} | {PerPixel(t.QuantumRuns, size)} | {N(t.Queries.QueriesConservative)} | {N(t.Logical.Ccz)} | {N(t.Logical.Measurements)} | {t.Logical.Qubits} | {Duration(frame.ClassicalTime(t.Name).TotalNanoseconds)} |");
        }
        text.AppendLine();
        for (var m = 0; m < models.Count; m++)
        {
            text.AppendLine($"### {models[m]}");
            text.AppendLine();
            text.AppendLine($"| scene | size | physical qubits | code distance | runtime, 1 QPU | runtime, {qpus} QPUs | runtime / classical | failure bound Σ | ε per run: qubits | code distance | runtime, 1 QPU |");
            text.AppendLine("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
            foreach (var (scene, size, frame) in Scenes)
            {
                var t = frame.Cost.Total;
                var (s, a) = (t.Split[m], t.Alone[m]);
                text.AppendLine($"| {scene} | {size}x{size} | {N(s.PhysicalQubits)} | {Distance(s)} | {Duration(s.SequentialNanoseconds)} | {Duration(s.ParallelNanoseconds)} | {FrameTable.Ratio(s.SequentialNanoseconds, frame.ClassicalTime(t.Name))} | {FrameTable.Probability(s.FailureBound)} | {N(a.PhysicalQubits)} | {Distance(a)} | {Duration(a.SequentialNanoseconds)} |");
            }
            text.AppendLine();
        }

        text.AppendLine("## Against the image size");
        text.AppendLine();
        text.AppendLine("Runs grow with the pixels, and the per-run budget ε / R shrinks with them, which raises the code distance a little.");
        text.AppendLine();
        text.AppendLine($"| scene | size | Grover runs per pixel | {string.Join(" | ", models.Select(m => $"{m.Name}: runtime per pixel"))} | classical per pixel |");
        text.AppendLine($"|---|---|---:|{string.Concat(models.Select(_ => "---:|"))}---:|");
        foreach (var (scene, size, frame) in Scenes)
        {
            var t = frame.Cost.Total;
            var pixels = (double)size * size;
            text.AppendLine($"| {scene} | {size}x{size} | {PerPixel(t.QuantumRuns, size)} | {string.Join(" | ", t.Split.Select(s => Duration(s.SequentialNanoseconds / pixels)))} | {Duration(frame.ClassicalTime(t.Name).TotalNanoseconds / pixels)} |");
        }
        text.AppendLine();

        text.AppendLine($"## Against the number of primitives (Qornell box, {ScalingSize}x{ScalingSize})");
        text.AppendLine();
        text.AppendLine("| N | Grover runs | #Eval, conservative | CCZ | logical qubits | classical render |");
        text.AppendLine("|---:|---:|---:|---:|---:|---:|");
        foreach (var (n, frame) in ByPrimitives)
        {
            var t = frame.Cost.Total;
            text.AppendLine($"| {n} | {N(t.QuantumRuns)} | {N(t.Queries.QueriesConservative)} | {N(t.Logical.Ccz)} | {t.Logical.Qubits} | {Duration(frame.ClassicalTime(t.Name).TotalNanoseconds)} |");
        }
        text.AppendLine();
        text.AppendLine("Runtime per frame on one QPU (ratio to the classical render):");
        text.AppendLine();
        text.AppendLine($"| N | {string.Join(" | ", models.Select(m => m.ToString()))} |");
        text.AppendLine($"|---:|{string.Concat(models.Select(_ => "---:|"))}");
        foreach (var (n, frame) in ByPrimitives)
        {
            var t = frame.Cost.Total;
            var classical = frame.ClassicalTime(t.Name);
            text.AppendLine($"| {n} | {string.Join(" | ", t.Split.Select(s => $"{Duration(s.SequentialNanoseconds)} ({FrameTable.Ratio(s.SequentialNanoseconds, classical)})"))} |");
        }
        text.AppendLine();
        text.AppendLine("Physical qubits per QPU (code distance):");
        text.AppendLine();
        text.AppendLine($"| N | {string.Join(" | ", models.Select(m => m.ToString()))} |");
        text.AppendLine($"|---:|{string.Concat(models.Select(_ => "---:|"))}");
        foreach (var (n, frame) in ByPrimitives)
            text.AppendLine($"| {n} | {string.Join(" | ", frame.Cost.Total.Split.Select(s => $"{N(s.PhysicalQubits)} ({Distance(s)})"))} |");
        text.AppendLine();
        if (plot is not null)
            text.AppendLine($"![Runtime per frame against N on each model, beside the classical render]({plot})").AppendLine();

        text.AppendLine($"## One frame pass by pass: {Detailed.Settings.Scene.Name}, {Detailed.Settings.Render.Width}x{Detailed.Settings.Render.Height}");
        text.AppendLine();
        text.Append(FrameTable.For(Detailed, machine).ToMarkdown("###"));
        text.AppendLine();

        text.AppendLine("## The paper's hardware run, for context");
        text.AppendLine();
        text.AppendLine($"The ray tracing paper ran its oracle search for 4 primitives on IBM's ibmq_paris (sec. 8, fig. 15): {SweepReport.PaperQubits} qubits, {SweepReport.PaperGates} gates,");
        text.AppendLine($"depth {SweepReport.PaperDepth} (its table 9), without error correction; the measured histogram was close to uniform, i.e. the search found nothing");
        text.AppendLine("the noise had not erased. The same search (our compact oracle for 4 primitives, one Grover iteration) under error correction, at the");
        text.AppendLine($"estimator's default budget of {FrameTable.Probability(QubitModel.ErrorBudget)} for the run ({PaperDevice.Subject.Label}, {PaperDevice.Logical.Qubits} logical qubits, {N(PaperDevice.Logical.Ccz)} CCZ):");
        text.AppendLine();
        text.AppendLine("| model | physical qubits | code distance | runtime |");
        text.AppendLine("|---|---:|---:|---:|");
        foreach (var p in PaperDevice.Physical)
            text.AppendLine($"| {p.Model} | {N(p.PhysicalQubits)} | {p.CodeDistance} | {Duration(p.RuntimeNanoseconds)} |");
        text.AppendLine();
        text.AppendLine("A frame is 10^4 to 10^6 such runs, on wider oracles.");
        return text.ToString();
    }

    private static string N(long value) => FrameTable.N(value);

    private static string Duration(double nanoseconds) => EstimateTable.Duration(nanoseconds);

    private static string Distance(FramePhysical p) => p.MinCodeDistance == p.MaxCodeDistance ? N(p.MaxCodeDistance) : $"{p.MinCodeDistance}–{p.MaxCodeDistance}";

    private static string PerPixel(long runs, int size) => (runs / ((double)size * size)).ToString("0.00", CultureInfo.InvariantCulture);
}
