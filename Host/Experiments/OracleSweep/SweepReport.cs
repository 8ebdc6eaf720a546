using System.Globalization;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Reports;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// docs/oracle-sweep.md: the oracle's estimates against the number of primitives and the coordinate bits,
/// before (baseline) and after (compact) the smaller construction, the unload trade-off, each change on
/// its own, physical figures, and the paper's table 9 beside ours.
/// </summary>
/// <param name="points">The oracle's estimates by N, coordinate bits and construction.</param>
/// <param name="models">The qubit models of the physical estimates.</param>
/// <param name="deviceExperiment">The estimates of <see cref="DeviceExperimentCircuits"/>, in order (empty: the section is left out).</param>
public sealed class SweepReport(IReadOnlyDictionary<(int Primitives, int Bits, string Construction), CircuitEstimate> points, IReadOnlyList<QubitModel> models,
    IReadOnlyList<CircuitEstimate>? deviceExperiment = null)
{
    /// <summary>The device experiment's circuits: the search run and the oracle alone, by default (compact) and for the device.</summary>
    public static readonly (EstimatedCircuit Circuit, OracleConstruction Construction)[] DeviceExperimentCircuits =
    [
        (EstimatedCircuits.SearchRun, OracleConstruction.Compact), (EstimatedCircuits.Oracle, OracleConstruction.Compact),
        (EstimatedCircuits.SearchRun, OracleConstruction.Device), (EstimatedCircuits.Oracle, OracleConstruction.Device),
    ];

    public const string Title = "Resource estimates of the gate-level oracle";

    /// <summary>Every estimate, by (N, coordinate bits, construction name).</summary>
    public IReadOnlyDictionary<(int Primitives, int Bits, string Construction), CircuitEstimate> Points => points;

    /// <summary>The paper's table 9: the oracle for 4 primitives in Qiskit.</summary>
    public const int PaperQubits = 19, PaperGates = 2165, PaperDepth = 1185;

    /// <summary>Table 9's second row: the same search transpiled for ibmq_paris (27 qubits).</summary>
    public const int DeviceQubits = 27, DeviceGates = 18277, DeviceDepth = 11096;

    /// <summary>Only the flat axis skipped: the in-plane change alone.</summary>
    public static readonly OracleConstruction InPlaneOnly = new("in-plane only", InPlaneAxes: true, BothBounds: false, MeasuredUnload: true);

    /// <summary>Only both bounds at once: the register change alone.</summary>
    public static readonly OracleConstruction BothBoundsOnly = new("both bounds only", InPlaneAxes: false, BothBounds: true, MeasuredUnload: true);

    /// <summary>The baseline unloading by lookup: the unload trade-off on the first construction.</summary>
    public static readonly OracleConstruction BaselineByLookup = OracleConstruction.Baseline with { Name = "baseline, lookup unload", MeasuredUnload = false };

    public static IReadOnlyList<OracleConstruction> Ablation => [OracleConstruction.Baseline, InPlaneOnly, BothBoundsOnly, OracleConstruction.Compact];

    /// <summary>Each construction with its measured unload, and the same unloading by lookup.</summary>
    private static readonly (OracleConstruction Measured, OracleConstruction Lookup)[] UnloadPairs =
        [(OracleConstruction.Baseline, BaselineByLookup), (OracleConstruction.Compact, OracleConstruction.Narrow)];

    private static void DeviceExperiment(Report report, IReadOnlyList<CircuitEstimate> estimates)
    {
        report.Heading("The paper's device experiment at the device's width (sec. 8, table 9)");
        report.Text($"""
            The ray tracing paper's sec. 8 ran one search over 4 primitives on a simulator and on ibmq_paris (27 qubits). Ours is
            `DeviceExperimentScene` (four squares on the 16x16x16 grid, the first camera ray of an 8x8 image that meets exactly one; the
            search run is the uniform preparation, one gate-level Grover iteration, the optimum at N = 4 and t = 1, and the index
            measured). Each row is attributed to where it comes from: the paper's two rows are its table 9, the simulator's circuit and
            the same circuit transpiled for the device; ours are the QDK's circuits of the `compact` (default) and `device`
            constructions, with gates in the QDK's intrinsics and with each CCX as Qiskit's 15.
            """);
        var table = new TextTable("device-experiment", ["circuit", "qubits", "gates (QDK)", "depth (QDK)", "gates (CCX as 15)", "depth (CCX as 15)", "fits ibmq_paris (27)"]).AlignRight(1, 2, 3, 4, 5);
        table.Row("paper's table 9: simulator", N(PaperQubits), "–", "–", N(PaperGates), N(PaperDepth), "yes");
        table.Row("paper's table 9: transpiled for ibmq_paris", N(DeviceQubits), "–", "–", N(DeviceGates), N(DeviceDepth), "yes");
        foreach (var ((circuit, construction), estimate) in DeviceExperimentCircuits.Zip(estimates))
        {
            var name = circuit == EstimatedCircuits.SearchRun ? "search run (prepare, 1 iteration, measure)" : "the oracle Int_r once";
            var qubits = estimate.Logical.Qubits;
            table.Row($"ours, {construction}: {name}", N(qubits),
                estimate.Counts is { } c ? N(c.Native.GateCount) : "–", estimate.Counts is { } d ? N(d.Native.Depth) : "–",
                estimate.Counts is { } e ? N(e.QiskitCcx.GateCount) : "–", estimate.Counts is { } f ? N(f.QiskitCcx.Depth) : "–",
                qubits <= DeviceQubits ? "yes" : $"no ({qubits - DeviceQubits} over)");
        }
        report.Table(table);
        report.Text("""
            Qubits are the peak in use, the library's auxiliaries included (the Resource Estimator's count). The paper's gate counts are
            in Qiskit's basis, closest to our CCX-as-15 columns; its transpiled row also pays for routing on the device's coupling map,
            which ours do not model. Z and CZ counts vary slightly run to run with the measurement-based uncomputation.
            """);
    }

    /// <summary>Every (N, bits, construction) point the report needs for the given sweeps.</summary>
    public static IEnumerable<(int Primitives, int Bits, OracleConstruction Construction)> Wanted(IReadOnlyList<int> primitives, IReadOnlyList<int> bits, IReadOnlyList<int> ablation)
    {
        var before = OracleConstruction.Baseline;
        var after = OracleConstruction.Compact;
        var wanted = new List<(int, int, OracleConstruction)>();
        foreach (var n in primitives)
            wanted.AddRange(UnloadPairs.SelectMany(p => new[] { p.Measured, p.Lookup }).Select(k => (n, EstimateSweep.DefaultCoordinateBits, k)));
        foreach (var c in bits) wanted.AddRange([(EstimateSweep.DefaultPrimitives, c, before), (EstimateSweep.DefaultPrimitives, c, after)]);
        foreach (var n in ablation) wanted.AddRange(Ablation.Select(k => (n, EstimateSweep.DefaultCoordinateBits, k)));
        if (primitives.Contains(4)) wanted.Add((4, EstimateSweep.DefaultCoordinateBits, OracleConstruction.Device));
        return wanted.DistinctBy(p => (p.Item1, p.Item2, p.Item3.Name));
    }

    /// <summary>The report.</summary>
    /// <param name="primitives">N of the sweep over primitives.</param>
    /// <param name="bits">Coordinate bits of the sweep over the grid.</param>
    /// <param name="ablation">N at which each change is measured alone.</param>
    /// <param name="plots">The sweep's plots, shown at the end.</param>
    public Report ToReport(IReadOnlyList<int> primitives, IReadOnlyList<int> bits, IReadOnlyList<int> ablation, IReadOnlyList<SweepPlots.Plot> plots)
    {
        var withCircuits = points.Values.All(p => p.Counts is not null);
        var c4 = EstimateSweep.DefaultCoordinateBits;
        var report = new Report(Title);
        report.Text($"""
            What the intersection oracle Int_r (paper sec. 4.2, figs. 3-5) costs as a circuit: the Microsoft Resource Estimator's logical counts
            and physical figures, and the gates and depth of the circuit the QDK extracts (`getCircuit`). Each point is one application of the
            oracle on fresh registers (`ApplyIntersectionOracleOnNewRegisters`: load, compare, XOR the flags' AND into an output qubit, uncompute),
            for the worst-case camera ray of a {EstimateSweep.ImageSize}x{EstimateSweep.ImageSize} image of a generated sweep scene (`SweepScene`: N rectangles on a c-bit integer grid; the ray
            whose search needs the most qubits, then the most depth bits; its first search, every depth and id accepted). `qrt estimate` gives the
            same figures, and those of a Grover iteration and a QSearch run, for any scene and pixel.
            """);

        report.Heading("The paper's table 9 beside ours (N = 4)");
        var table9 = new TextTable("table-9", ["oracle", "qubits", "gates", "depth", "basis"]).AlignRight(1, 2, 3);
        table9.Row("paper, simulator (Qiskit)", N(PaperQubits), N(PaperGates), N(PaperDepth), "Qiskit's, after its decomposition (not stated further)");
        table9.Row("paper, transpiled for ibmq_paris", N(DeviceQubits), N(DeviceGates), N(DeviceDepth), "the device's native gates, routed on its 27 qubits");
        foreach (var construction in new[] { OracleConstruction.Baseline, OracleConstruction.Compact, OracleConstruction.Narrow, OracleConstruction.Device })
        {
            if (!points.TryGetValue((4, c4, construction.Name), out var p)) continue;
            if (p.Counts is { } counts)
            {
                table9.Row($"ours, {construction}", N(p.Logical.Qubits), N(counts.Native.GateCount), N(counts.Native.Depth), "QDK intrinsics (CCX is one gate)");
                table9.Row($"ours, {construction}", N(p.Logical.Qubits), N(counts.QiskitCcx.GateCount), N(counts.QiskitCcx.Depth), "CCX as Qiskit's 15 Clifford+T gates");
            }
            else table9.Row($"ours, {construction}", N(p.Logical.Qubits), "–", "–", "(circuit not extracted)");
        }
        report.Table(table9);
        report.Text("""
            How the bases differ. The QDK's circuit is the trace of the simulator's intrinsic gates: X, H, S, T, rotations, CX, CZ and
            CCX (a Toffoli is one gate), with measurements and resets listed apart. The standard library uncomputes every AND and every
            table lookup by measurement: an X-basis measurement and, on some outcomes, a CZ or Z, where a unitary circuit (as Qiskit's
            multi-controlled gates build) spends a second Toffoli. Qiskit reports counts after decomposing to its basis, typically single-
            qubit gates and CX, where a Toffoli is 15 gates (2 H, 6 CX, 7 T/T†) and depth 11; the second row of each of ours replaces
            every CCX by exactly that definition, which is the closer comparison, though Qiskit's transpiler would also merge adjacent
            single-qubit gates. Qubits are not basis-dependent: ours count the peak in use, the standard library's auxiliary qubits
            (lookup helpers, comparator carries, the unlookup's power products) included.

            `device` is the construction for a machine of few qubits (`--oracle device`): the point is still loaded per axis from the
            ray's table, but no bound is: each axis step compares the point with every primitive's minimum and maximum as classical
            constants, each comparison controlled on the index register holding that primitive (2N controlled comparators per
            axis instead of a bound register and its lookups), and validity is a classical fact too: a row without a point, or an
            index past the last primitive, clears its first axis flag under index control. It drops the 2c qubits of the bound
            registers and the valid qubit (the device experiment's figures are in the next section). Its gates grow with N faster
            than `compact`'s (the comparators are per primitive), so it is for small device experiments, not renders.
            Like every construction it is checked against verify-rpc on every basis state (`GateOracleTests`).
            """);

        if (deviceExperiment is { Count: > 0 }) DeviceExperiment(report, deviceExperiment);

        report.Heading($"The oracle against the number of primitives ({c4}-bit grid), before → after");
        report.Text($"""
            Before: `{OracleConstruction.Baseline}`, the oracle as first built (commit 97cb017; the same circuit, kept as `--oracle baseline`): x, y and z
            tested for every primitive, minimum then maximum in one register, so 6 lookups and an unlookup per computation. After:
            `{OracleConstruction.Compact}`, the default: only the two axes in each primitive's plane (on the flat axis the point is the plane and
            min = max, so that test always passes) and both bounds loaded at once, so 2 lookups and an unlookup, for one more coordinate
            register and one flag fewer. Every construction is checked against verify-rpc on every basis state (`GateOracleTests`).
            """);
        report.Table(SweepTable("by-primitives", "N", primitives.Select(n => (N(n), (n, c4))), withCircuits));

        report.Heading($"The oracle against the coordinate bits (N = {EstimateSweep.DefaultPrimitives}), before → after");
        report.Table(SweepTable("by-bits", "bits", bits.Select(c => (N(c), (EstimateSweep.DefaultPrimitives, c))), withCircuits));

        report.Heading("Unload by measurement or by lookup");
        report.Text("""
            Both constructions above clear the loaded registers with the standard library's measurement-based unlookup (`Adjoint Select`:
            X-basis measurements, then a phase lookup over the index register built from power products, which needs
            2^⌊n/2⌋ + 2^⌈n/2⌉ − n − 2 auxiliary qubits). Unloading with a second lookup of the same data instead (`narrow` is `compact` so built)
            needs only the lookup's n − 1 helpers but a lookup's Toffolis. Figures are measured → lookup.
            """);
        var unload = new TextTable("unload", ["N", .. UnloadPairs.SelectMany(p => new[] { $"{p.Measured}: qubits", "CCZ", "CCZ change" })]);
        unload.AlignRight(Enumerable.Range(0, unload.Header.Count));
        foreach (var n in primitives)
        {
            var cells = new List<string> { N(n) };
            foreach (var (measured, lookup) in UnloadPairs)
            {
                if (points.TryGetValue((n, c4, measured.Name), out var m) && points.TryGetValue((n, c4, lookup.Name), out var l))
                    cells.AddRange([Arrow(m.Logical.Qubits, l.Logical.Qubits), Arrow(m.Logical.Ccz, l.Logical.Ccz), Change(m.Logical.Ccz, l.Logical.Ccz)]);
                else cells.AddRange(["–", "–", "–"]);
            }
            unload.Row(cells);
        }
        report.Table(unload);
        report.Text("""
            The unlookup's power products set the peak width from N = 32 on; the lookup keeps it at the registers plus n − 1. The Toffoli
            price of the lookup is the same two extra lookups per oracle call in both constructions, so it weighs more, relative to the
            rest, in the compact one, which has fewer lookups to begin with.
            """);

        report.Heading("Each change on its own");
        var changes = new TextTable("each-change", ["N", "construction", "axes", "bound registers", "qubits", "CCZ", "measurements", .. withCircuits ? new[] { "gates (QDK)", "depth (QDK)" } : []]);
        changes.AlignRight(Enumerable.Range(0, changes.Header.Count).Where(k => k != 1));
        foreach (var n in ablation)
            foreach (var construction in Ablation)
            {
                if (!points.TryGetValue((n, c4, construction.Name), out var p)) continue;
                string[] circuit = p.Counts is { } counts ? [N(counts.Native.GateCount), N(counts.Native.Depth)] : withCircuits ? ["–", "–"] : [];
                changes.Row([N(n), construction.ToString(), N(construction.Axes), N(construction.BoundRegisters), N(p.Logical.Qubits), N(p.Logical.Ccz), N(p.Logical.Measurements), .. circuit]);
            }
        report.Table(changes);

        report.Heading($"Physical estimates ({OracleConstruction.Compact}, {c4}-bit grid)");
        var physical = new TextTable("physical", ["N", .. models.SelectMany(m => new[] { $"{m}: physical qubits", "runtime", "code distance" })]);
        physical.AlignRight(Enumerable.Range(0, physical.Header.Count));
        foreach (var n in primitives)
        {
            if (!points.TryGetValue((n, c4, OracleConstruction.Compact.Name), out var p)) continue;
            physical.Row([N(n), .. p.Physical.SelectMany(e => new[] { N(e.PhysicalQubits), EstimateTable.Duration(e.RuntimeNanoseconds), N(e.CodeDistance) })]);
        }
        report.Table(physical);

        if (plots.Count > 0)
        {
            report.Heading("Plots");
            foreach (var plot in plots) report.Text($"{plot.Caption}:").Plot(plot.Suffix, plot.Spec, plot.Caption);
        }

        report.Heading("Conventions");
        report.Text(string.Join('\n', EstimateTable.Conventions(withCircuits).Select(note => $"- {note}")
            .Append("- \"a → b\": the baseline construction's figure, then the compact one's, on the same ray.")));
        return report;
    }

    private TextTable SweepTable(string name, string key, IEnumerable<(string Label, (int Primitives, int Bits) Point)> rows, bool withCircuits)
    {
        var table = new TextTable(name, [key, "depth bits", "qubits", "ancillas", "CCZ", "measurements",
            .. withCircuits ? new[] { "gates (QDK)", "depth (QDK)", "gates (CCX as 15)", "depth (CCX as 15)" } : []]);
        table.AlignRight(Enumerable.Range(0, table.Header.Count));
        foreach (var (label, (n, c)) in rows)
        {
            if (!points.TryGetValue((n, c, OracleConstruction.Baseline.Name), out var b) || !points.TryGetValue((n, c, OracleConstruction.Compact.Name), out var a)) continue;
            List<string> cells = [label, N(a.Subject.Oracle.Table.DepthBits), Arrow(b.Logical.Qubits, a.Logical.Qubits), Arrow(b.Registers!.Value.AncillaQubits, a.Registers!.Value.AncillaQubits),
                Arrow(b.Logical.Ccz, a.Logical.Ccz), Arrow(b.Logical.Measurements, a.Logical.Measurements)];
            if (withCircuits && b.Counts is { } bc && a.Counts is { } ac)
                cells.AddRange([Arrow(bc.Native.GateCount, ac.Native.GateCount), Arrow(bc.Native.Depth, ac.Native.Depth), Arrow(bc.QiskitCcx.GateCount, ac.QiskitCcx.GateCount), Arrow(bc.QiskitCcx.Depth, ac.QiskitCcx.Depth)]);
            table.Row(cells);
        }
        return table;
    }

    private static string N(long value) => value.ToString(CultureInfo.InvariantCulture);

    private static string Arrow(long before, long after) => $"{before} → {after}";

    private static string Change(long before, long after) =>
        before == 0 ? "–" : ((after - before) / (double)before).ToString("+0%;-0%;0%", CultureInfo.InvariantCulture);
}
