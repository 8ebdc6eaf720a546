using System.Globalization;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// The estimates of several circuits as one table: measures as rows (so it fits a terminal), one
/// column per circuit, the counting conventions as notes.
/// </summary>
public static class EstimateTable
{
    /// <summary>Gate kinds in the order rows list them; kinds not named here follow alphabetically.</summary>
    private static readonly string[] KindOrder = ["X", "CX", "CCX", "Y", "Z", "CZ", "H", "S", "S†", "T", "T†", "Rx", "Ry", "Rz", "SWAP"];

    /// <summary>The lines that say what was estimated: scene, ray, registers, construction, r.</summary>
    public static IReadOnlyList<string> Context(Scenes.Scene scene, SceneGeometry geometry, EstimateSubject subject)
    {
        var table = subject.Oracle.Table;
        var ray = table.Ray;
        var construction = subject.Oracle.Construction;
        return
        [
            $"scene: {scene.Name}: N = {geometry.Count}, {scene.Grid}",
            $"ray: {subject.Label}, origin {ray.Origin}, direction {ray.Direction}; its first search (full range: every depth, every id; marked rows: {table.Marked(subject.Oracle.Window).MarkedCount})",
            $"registers: {geometry.IndexBits} index, {table.CoordinateBits} bits per coordinate, {table.DepthBits} depth bits",
            $"oracle construction: {construction} ({(construction.InPlaneAxes ? "the two in-plane axes" : "all three axes")}, {(construction.ConstantBounds ? "bounds as constants under index control" : construction.BothBounds ? "both bounds loaded at once" : "minimum then maximum in one register")}, {(construction.MeasuredUnload ? "unload by measurement" : "unload by lookup")})",
            $"QSearch run: r = {subject.Iterations.ToString(CultureInfo.InvariantCulture)} iterations",
        ];
    }

    /// <summary>The line that says what a pooled query was estimated for: its pool, pair register and rows.</summary>
    public static string PoolContext(SceneGeometry geometry, IReadOnlyList<OracleInput> pool, string label)
    {
        var rayBits = pool.Count <= 1 ? 0 : 32 - int.LeadingZeroCount(pool.Count - 1);
        var depthBits = pool.Max(p => p.Table.DepthBits) + 1;
        var rows = (long)pool.Count << geometry.IndexBits;
        return $"pool: {label}; pair register {geometry.IndexBits} primitive + {rayBits} ray qubits, rows looked up over {N(rows)} pairs, windows over {N(pool.Count)} rays, {depthBits} depth bits (the widest ray's + 1)";
    }

    public static ReportTable For(string title, IReadOnlyList<CircuitEstimate> estimates, IReadOnlyList<QubitModel> models, IReadOnlyList<string> context)
    {
        var table = new ReportTable(title, "measure", estimates.Select(e => e.Circuit.Name).ToArray());
        foreach (var line in context) table.Context(line);
        void Row(string measure, Func<CircuitEstimate, string> value) => table.Row(measure, estimates.Select(value));

        Row("logical qubits (estimator)", e => N(e.Logical.Qubits));
        Row("  modelled: index + work + output + auxiliary", e => e.Registers is { } r
            ? $"{r.IndexQubits} + {r.WorkQubits} + {Intersection.OracleRegisters.OutputQubits} + {r.AuxiliaryQubits} = {r.PeakQubits}" : "–");
        Row("  ancillas: work + auxiliary", e => e.Registers is { } r ? N(r.AncillaQubits) : "–");
        Row("T", e => N(e.Logical.T));
        Row("rotations", e => N(e.Logical.Rotations));
        Row("CCZ", e => N(e.Logical.Ccz));
        Row("CCiX", e => N(e.Logical.Ccix));
        Row("measurements", e => N(e.Logical.Measurements));

        var counted = estimates.Where(e => e.Counts is not null).ToArray();
        if (counted.Length > 0)
        {
            Row("circuit (getCircuit)", e => e.Counts is { } c ? c.Extrapolated ? $"r = 1, 2 traced, r = {e.Subject.Iterations} extrapolated" : "traced" : "–");
            Row("gates, QDK basis", e => e.Counts is { } c ? N(c.Native.GateCount) : "–");
            foreach (var kind in Kinds(counted))
                Row($"  {kind}{(CircuitCounts.OutcomeDependentKinds.Contains(kind) ? " *" : "")}", e => e.Counts is { } c ? N(c.Native.Gate(kind)) : "–");
            Row("measurements / resets", e => e.Counts is { } c ? $"{N(c.Native.Measurements)} / {N(c.Native.Resets)}" : "–");
            Row("depth, QDK basis *", e => e.Counts is { } c ? N(c.Native.Depth) : "–");
            Row("gates, CCX as Qiskit's 15 (Clifford+T)", e => e.Counts is { } c ? N(c.QiskitCcx.GateCount) : "–");
            Row("depth, CCX as Qiskit's 15 *", e => e.Counts is { } c ? N(c.QiskitCcx.Depth) : "–");
        }

        for (var m = 0; m < models.Count; m++)
        {
            var k = m;
            Row($"{models[k]}: physical qubits", e => N(e.Physical[k].PhysicalQubits));
            Row($"{models[k]}: runtime", e => Duration(e.Physical[k].RuntimeNanoseconds));
            Row($"{models[k]}: code distance", e => N(e.Physical[k].CodeDistance));
        }

        foreach (var note in Conventions(counted.Length > 0, counted.Any(e => e.Counts!.Extrapolated))) table.Note(note);
        return table;
    }

    /// <summary>How every figure is counted, printed under each table.</summary>
    public static IEnumerable<string> Conventions(bool withCircuits, bool extrapolated = false)
    {
        yield return "Logical counts: the Microsoft Resource Estimator (qsharp-lang 1.32.5-dev). Qubits = peak in use, library auxiliaries included; an AND into a fresh qubit counts as one CCZ and its measurement-based uncomputation as one measurement; T and rotations are single-qubit gates.";
        yield return "Modelled (OracleRegisters): index ceil(log2 N) + work (rpc, bound registers, depth, flags) + output + the widest library step's auxiliaries; ancillas = work + auxiliaries, all back in |0> after each oracle call.";
        if (withCircuits)
        {
            yield return "Gates: getCircuit's trace of one simulated run, in the QDK's intrinsic gate set (X, H, S, T, rotations, CX, CZ, CCX, SWAP); measurements and resets are listed apart, not counted as gates. Not Qiskit's basis: a CCX is one gate here.";
            yield return "Depth: every operation (measurements and resets too) takes one step on each qubit it touches and starts when they are all free: Qiskit's QuantumCircuit.depth() on the same list.";
            yield return "CCX as Qiskit's 15: every CCX replaced by Qiskit's ccx definition (2 H, 6 CX, 4 T, 3 T†), other gates kept: comparable with gate counts Qiskit reports for Toffoli circuits.";
            if (extrapolated) yield return $"Extrapolated: a QSearch run with r > {ResourceEstimator.TracedRepeats} is traced with r = 1 and r = 2 and counted as run(1) + (r − 1) · (run(2) − run(1)), every figure (each iteration is the same circuit; the QDK's extraction slows down more than linearly with length).";
            yield return "* Z and CZ (and so the depth) include the phase corrections the uncomputations apply after measuring, which depend on that run's random outcomes and vary a little between runs.";
        }
        yield return $"Physical: the estimator's predefined qubit models, error budget {QubitModel.ErrorBudget.ToString(CultureInfo.InvariantCulture)}, other parameters at their defaults; runtime of one execution of the circuit.";
        yield return "Queries (docs/conventions.md): a QSearch run with r iterations is r oracle queries in the paper's count, r + 1 in the conservative count (the preparation counted as one).";
    }

    private static IEnumerable<string> Kinds(IEnumerable<CircuitEstimate> estimates)
    {
        var present = estimates.SelectMany(e => e.Counts!.Native.Gates.Keys).ToHashSet();
        return KindOrder.Where(present.Contains).Concat(present.Except(KindOrder).Order(StringComparer.Ordinal));
    }

    public static string N(long value) => value.ToString(CultureInfo.InvariantCulture);

    /// <summary>A runtime in nanoseconds as ns, µs, ms, s, or hours when long.</summary>
    public static string Duration(double nanoseconds) => nanoseconds switch
    {
        < 1e3 => $"{nanoseconds.ToString("0", CultureInfo.InvariantCulture)} ns",
        < 1e6 => $"{(nanoseconds / 1e3).ToString("0.##", CultureInfo.InvariantCulture)} µs",
        < 1e9 => $"{(nanoseconds / 1e6).ToString("0.##", CultureInfo.InvariantCulture)} ms",
        < 3.6e12 => $"{(nanoseconds / 1e9).ToString("0.##", CultureInfo.InvariantCulture)} s",
        _ => $"{(nanoseconds / 3.6e12).ToString("0.##", CultureInfo.InvariantCulture)} h",
    };
}
