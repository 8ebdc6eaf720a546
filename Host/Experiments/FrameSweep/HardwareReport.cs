using System.Globalization;
using QuantumRayTracing.Experiments;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// docs/frame-sweep.md: what whole frames cost on fault-tolerant machines. The scenes at several image
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
    public const string Title = "What a frame costs on a fault-tolerant machine";

    /// <summary>The name of the runtime plot, written as &lt;report&gt;-runtime-vs-primitives.png.</summary>
    public const string RuntimePlot = "runtime-vs-primitives";

    /// <summary>The report; <paramref name="machine"/> names what the classical renders were timed on.</summary>
    public Report ToReport(string machine)
    {
        var first = Detailed;
        var models = first.Cost.Models;
        var qpus = first.Cost.Qpus;
        var budget = first.Settings.ErrorBudget;
        var report = new Report(Title);
        report.Text("""
            `qrt estimate` prices one ray's circuits; a frame is about 10^5 Grover runs of many lengths over primary, specular and shadow
            rays. `qrt estimate --frame` renders a frame with the analytic engine (the same searches as `render --engine analytic` with the
            same options and seed, but for the budget rounds, which confirm each ray with a search of its own: a pooled search over
            many rays' pairs has no circuit to price), records every Grover run at the engine seam (pass, engine batch, N, r, oracle shape), prices each run's
            gate-level circuit with the Microsoft Resource Estimator, and sums. This report applies it to the paper's scenes.
            """);
        report.Text($"The machine named at the end was shared with other work while this ran: a classical wall time is the fastest of at least {FrameEstimate.ClassicalRepeats} renders (more while they took under {FrameEstimate.ClassicalTimingBudget.TotalSeconds} s together), and still noisy.");
        var headline = Detailed.Cost.Total;
        var options = Detailed.Settings.Render;
        var summary = new List<string> { $"In short: a {options.Width}x{options.Height} frame of the {Detailed.Settings.Scene.Name} makes {N(headline.QuantumRuns)} Grover runs ({N(headline.Logical.Ccz)} CCZ in all)." };
        for (var m = 0; m < models.Count; m++)
        {
            var p = headline.Split[m];
            summary.Add($"On {models[m]} it needs {N(p.PhysicalQubits)} physical qubits at code distance up to {p.MaxCodeDistance} and {Duration(p.SequentialNanoseconds)} on one QPU ({Duration(p.ParallelNanoseconds)} on {qpus}),");
            summary.Add($"{FrameTable.Ratio(p.SequentialNanoseconds, Detailed.ClassicalTime(headline.Name))} the classical render's {Duration(Detailed.ClassicalTime(headline.Name).TotalNanoseconds)} here.");
        }
        report.Text(string.Join('\n', summary));

        report.Heading("How a frame is priced");
        report.Text($"""
            - A Grover run with r ≥ 1 is one QSearch run circuit: prepare the uniform superposition over the N primitives, r Grover iterations with the
              gate-level intersection oracle ({first.Settings.Construction} construction), measure. Runs with r = 0 sample a uniform index, which needs no quantum processor.
            - Its cost depends only on the oracle's shape (N, index, coordinate and depth bits, and how many bits each comparator with a constant
              compares) and r. The estimator traces each shape's circuit with r = 1 and r = 2; r iterations have exactly run(1) + (r − 1) · (run(2) − run(1))
              logical operations; each distinct set of counts is priced by the estimator from the counts (`AccountForEstimates`). A test renders a 4x4
              frame and checks every figure against each run's own circuit estimated on its own.
            - Error budget: the frame may fail with probability at most ε = {FrameTable.Probability(budget)}. It fails only if one of its R runs fails, so giving
              each run ε / R keeps it within ε (union bound); each run's failure bound (logical error rate x logical qubits x cycles + T-state error
              rate x T states, from the estimator's own figures) is summed and shown. "ε per run" prices every run with the whole ε instead: the
              cheaper machine of a frame that may fail R times as often.
            - Physical qubits: the widest run's, algorithm and T factories (what each processor holds). Runtime, 1 QPU: the runs one after another.
              Runtime, {qpus} QPUs: the render's engine batches (a round of a pass) one after another, each batch's runs placed longest first on the
              processor free earliest. Code distance: the range the estimator chose over the runs; each run is priced at its own. A machine
              fixed at the largest stays within the budget and runs a run of distance d up to d_max / d slower (a logical cycle lasts in
              proportion to the distance).
            - Classical: the brute-force reference render of the same frame (every primitive tested, no pipeline tricks) on this machine, whole render
              wall time. The ratio is quantum runtime on one QPU over it. Lookup-table preparation and the host's classical work are not in the quantum runtime.
            - Queries: a run with r ≥ 1 is r + 1 oracle queries in the conservative count, r in the paper's; both are the render's own #Eval.
            - Render options: the defaults of `render` (neighbours, shadow neighbours, exact termination, lattice), seed {first.Settings.Render.Seed}.
            """);

        report.Heading("The paper's scenes");
        var scenes = new TextTable("scenes", ["scene", "size", "Grover runs", "per pixel", "#Eval, conservative", "CCZ", "measurements", "logical qubits", "classical render"])
            .AlignRight(Enumerable.Range(2, 7));
        foreach (var (scene, size, frame) in Scenes)
        {
            var t = frame.Cost.Total;
            scenes.Row(scene, $"{size}x{size}", N(t.QuantumRuns), PerPixel(t.QuantumRuns, size), N(t.Queries.QueriesConservative), N(t.Logical.Ccz), N(t.Logical.Measurements),
                t.Logical.Qubits.ToString(CultureInfo.InvariantCulture), Duration(frame.ClassicalTime(t.Name).TotalNanoseconds));
        }
        report.Table(scenes);
        for (var m = 0; m < models.Count; m++)
        {
            report.Heading(models[m].ToString(), level: 3);
            var onModel = new TextTable($"scenes-model-{m + 1}", ["scene", "size", "physical qubits", "code distance", "runtime, 1 QPU", $"runtime, {qpus} QPUs", "runtime / classical",
                "failure bound Σ", "ε per run: qubits", "code distance", "runtime, 1 QPU"]).AlignRight(Enumerable.Range(2, 9));
            foreach (var (scene, size, frame) in Scenes)
            {
                var t = frame.Cost.Total;
                var (s, a) = (t.Split[m], t.Alone[m]);
                onModel.Row(scene, $"{size}x{size}", N(s.PhysicalQubits), Distance(s), Duration(s.SequentialNanoseconds), Duration(s.ParallelNanoseconds),
                    FrameTable.Ratio(s.SequentialNanoseconds, frame.ClassicalTime(t.Name)), FrameTable.Probability(s.FailureBound), N(a.PhysicalQubits), Distance(a), Duration(a.SequentialNanoseconds));
            }
            report.Table(onModel);
        }

        report.Heading("Against the image size");
        report.Text("Runs grow with the pixels, and the per-run budget ε / R shrinks with them, which raises the code distance a little.");
        var perPixel = new TextTable("per-pixel", ["scene", "size", "Grover runs per pixel", .. models.Select(m => $"{m.Name}: runtime per pixel"), "classical per pixel"])
            .AlignRight(Enumerable.Range(2, models.Count + 2));
        foreach (var (scene, size, frame) in Scenes)
        {
            var t = frame.Cost.Total;
            var pixels = (double)size * size;
            perPixel.Row([scene, $"{size}x{size}", PerPixel(t.QuantumRuns, size), .. t.Split.Select(s => Duration(s.SequentialNanoseconds / pixels)), Duration(frame.ClassicalTime(t.Name).TotalNanoseconds / pixels)]);
        }
        report.Table(perPixel);

        report.Heading($"Against the number of primitives (Qornell box, {ScalingSize}x{ScalingSize})");
        var byN = new TextTable("by-primitives", ["N", "Grover runs", "#Eval, conservative", "CCZ", "logical qubits", "classical render"]).AlignRight(Enumerable.Range(0, 6));
        foreach (var (n, frame) in ByPrimitives)
        {
            var t = frame.Cost.Total;
            byN.Row(n.ToString(CultureInfo.InvariantCulture), N(t.QuantumRuns), N(t.Queries.QueriesConservative), N(t.Logical.Ccz), t.Logical.Qubits.ToString(CultureInfo.InvariantCulture),
                Duration(frame.ClassicalTime(t.Name).TotalNanoseconds));
        }
        report.Table(byN);
        report.Text("Runtime per frame on one QPU (ratio to the classical render):");
        var runtime = new TextTable("runtime-by-primitives", ["N", .. models.Select(m => m.ToString())]).AlignRight(Enumerable.Range(0, models.Count + 1));
        foreach (var (n, frame) in ByPrimitives)
        {
            var t = frame.Cost.Total;
            var classical = frame.ClassicalTime(t.Name);
            runtime.Row([n.ToString(CultureInfo.InvariantCulture), .. t.Split.Select(s => $"{Duration(s.SequentialNanoseconds)} ({FrameTable.Ratio(s.SequentialNanoseconds, classical)})")]);
        }
        report.Table(runtime);
        Scaling(report, models);
        report.Text("Physical qubits per QPU (code distance):");
        var qubits = new TextTable("qubits-by-primitives", ["N", .. models.Select(m => m.ToString())]).AlignRight(Enumerable.Range(0, models.Count + 1));
        foreach (var (n, frame) in ByPrimitives)
            qubits.Row([n.ToString(CultureInfo.InvariantCulture), .. frame.Cost.Total.Split.Select(s => $"{N(s.PhysicalQubits)} ({Distance(s)})")]);
        report.Table(qubits);
        report.Plot(RuntimePlot, FramePlots.RuntimeAgainstPrimitives($"Runtime per frame, Qornell box, {ScalingSize}x{ScalingSize}, one QPU",
                ByPrimitives.Select(p => p.Primitives).ToArray(),
                models.Select((m, i) => (m.ToString(), (IReadOnlyList<double>)ByPrimitives.Select(p => p.Frame.Cost.Total.Split[i].SequentialNanoseconds / 1e9).ToArray())).ToArray(),
                ByPrimitives.Select(p => p.Frame.ClassicalTime(p.Frame.Cost.Total.Name).TotalSeconds).ToArray()),
            "Runtime per frame against N on each model, beside the classical render");

        report.Heading($"One frame pass by pass: {Detailed.Settings.Scene.Name}, {Detailed.Settings.Render.Width}x{Detailed.Settings.Render.Height}");
        report.Table(FrameTable.For(Detailed, machine));

        report.Heading("The paper's hardware run, for context");
        report.Text($"""
            The ray tracing paper ran its oracle search for 4 primitives on a simulator and on IBM's ibmq_paris (sec. 8, fig. 15), without error
            correction. Its table 9 gives the simulator's circuit as {SweepReport.PaperQubits} qubits, {N(SweepReport.PaperGates)} gates and depth {N(SweepReport.PaperDepth)}, and the circuit
            transpiled for ibmq_paris as {NoiseReport.DeviceQubits} qubits, {N(NoiseReport.DeviceGates)} gates and depth {N(NoiseReport.DeviceDepth)}; the device's measured histogram was
            close to uniform, i.e. the search found nothing the noise had not erased. The same search (our compact oracle for 4 primitives, one Grover iteration) under error correction, at the
            estimator's default budget of {FrameTable.Probability(QubitModel.ErrorBudget)} for the run ({PaperDevice.Subject.Label}, {PaperDevice.Logical.Qubits} logical qubits, {N(PaperDevice.Logical.Ccz)} CCZ):
            """);
        var device = new TextTable("paper-device", ["model", "physical qubits", "code distance", "runtime"]).AlignRight(1, 2, 3);
        foreach (var p in PaperDevice.Physical)
            device.Row(p.Model.ToString(), N(p.PhysicalQubits), p.CodeDistance.ToString(CultureInfo.InvariantCulture), Duration(p.RuntimeNanoseconds));
        report.Table(device);
        report.Text("A frame is 10^4 to 10^6 such runs, on wider oracles.");
        return report;
    }

    /// <summary>
    /// Data loading, said plainly, and the fits of runtime against N: the gate-level oracle computes every primitive's test in
    /// gates, so its gates grow linearly in N and a search costs about √N · N gates against N classical tests.
    /// </summary>
    private void Scaling(Report report, IReadOnlyList<QubitModel> models)
    {
        var primitives = ByPrimitives.Select(p => p.Primitives).ToArray();
        var rows = RuntimeScaling.Fit(primitives,
            models.Select((m, i) => (m.ToString(), (IReadOnlyList<double>)ByPrimitives.Select(p => p.Frame.Cost.Total.Split[i].SequentialNanoseconds / 1e9).ToArray())).ToArray(),
            ByPrimitives.Select(p => p.Frame.ClassicalTime(p.Frame.Cost.Total.Name).TotalSeconds).ToArray());
        if (rows.Count == 0) return;
        var classical = rows[0].Classical;
        report.Text($"""
            **Data loading.** The gate-level oracle loads each primitive's bounds into the circuit and tests it in gates, so its gate count
            grows linearly in N (docs/oracle-sweep.md): a Grover run of about √N iterations costs about √N · N gates, against N classical
            tests for brute force. Fits of log runtime on log N (least squares over N = {primitives.Min()} … {primitives.Max()}, {ScalingSize}x{ScalingSize},
            one QPU; residual: root-mean-square in log10), beside the classical render's, N^{RuntimeScaling.G(classical.Exponent)} (residual {classical.Residual.ToString("0.00", CultureInfo.InvariantCulture)}):
            """);
        var fits = new TextTable("runtime-fits", ["model", "quantum runtime ∝ N^b, b", "residual", "classical ∝ N^b, b", "where the fits cross"]).AlignRight(1, 2, 3);
        foreach (var row in rows)
            fits.Row(row.Model, RuntimeScaling.G(row.Quantum.Exponent), row.Quantum.Residual.ToString("0.00", CultureInfo.InvariantCulture),
                RuntimeScaling.G(row.Classical.Exponent), row.CrossingText());
        report.Table(fits);
        report.Text("A fit states the trend over the measured N only: the frames' run counts and the code distances change with N too, and the classical times are single wall times on a shared machine.");
    }

    private static string N(long value) => FrameTable.N(value);

    private static string Duration(double nanoseconds) => EstimateTable.Duration(nanoseconds);

    private static string Distance(FramePhysical p) => p.MinCodeDistance == p.MaxCodeDistance ? N(p.MaxCodeDistance) : $"{p.MinCodeDistance}–{p.MaxCodeDistance}";

    private static string PerPixel(long runs, int size) => (runs / ((double)size * size)).ToString("0.00", CultureInfo.InvariantCulture);
}
