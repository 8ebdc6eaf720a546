using System.Globalization;
using System.Text;
using QuantumRayTracing.Intersection;

namespace QuantumRayTracing.Estimates;

/// <summary>
/// docs/estimates.md: the oracle's estimates against the number of primitives and the coordinate bits,
/// before (baseline) and after (compact) the smaller construction, the unload trade-off, each change on
/// its own, physical figures, and the paper's table 9 beside ours.
/// </summary>
public sealed class SweepReport(IReadOnlyDictionary<(int Primitives, int Bits, string Construction), CircuitEstimate> points, IReadOnlyList<QubitModel> models)
{
    /// <summary>Every estimate, by (N, coordinate bits, construction name).</summary>
    public IReadOnlyDictionary<(int Primitives, int Bits, string Construction), CircuitEstimate> Points => points;

    /// <summary>The paper's table 9: the oracle for 4 primitives in Qiskit.</summary>
    public const int PaperQubits = 19, PaperGates = 2165, PaperDepth = 1185;

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
        return wanted.DistinctBy(p => (p.Item1, p.Item2, p.Item3.Name));
    }

    /// <summary>The report's Markdown.</summary>
    /// <param name="primitives">N of the sweep over primitives.</param>
    /// <param name="bits">Coordinate bits of the sweep over the grid.</param>
    /// <param name="ablation">N at which each change is measured alone.</param>
    /// <param name="command">The command line that regenerates the report.</param>
    /// <param name="machine">What the estimates ran on.</param>
    /// <param name="plots">PNG files written beside the report (relative paths) with their captions, shown at the end.</param>
    public string Markdown(IReadOnlyList<int> primitives, IReadOnlyList<int> bits, IReadOnlyList<int> ablation, string command, string machine,
        IReadOnlyList<(string File, string Caption)> plots)
    {
        var withCircuits = points.Values.All(p => p.Counts is not null);
        var c4 = EstimateSweep.DefaultCoordinateBits;
        var text = new StringBuilder();
        text.AppendLine("# Resource estimates of the gate-level oracle");
        text.AppendLine();
        text.AppendLine("What the intersection oracle Int_r (paper sec. 4.2, figs. 3-5) costs as a circuit: the Microsoft Resource Estimator's logical counts");
        text.AppendLine("and physical figures, and the gates and depth of the circuit the QDK extracts (`getCircuit`). Each point is one application of the");
        text.AppendLine("oracle on fresh registers (`ApplyIntersectionOracleOnNewRegisters`: load, compare, XOR the flags' AND into an output qubit, uncompute),");
        text.AppendLine($"for the worst-case camera ray of a {EstimateSweep.ImageSize}x{EstimateSweep.ImageSize} image of a generated sweep scene (`SweepScene`: N rectangles on a c-bit integer grid; the ray");
        text.AppendLine("whose search needs the most qubits, then the most depth bits; its first search, every depth and id accepted). `qrt estimate` gives the");
        text.AppendLine("same figures, and those of a Grover iteration and a QSearch run, for any scene and pixel.");
        text.AppendLine();
        text.AppendLine($"Regenerate: `{command}` (under a minute on 2 cores). Machine: {machine}.");
        text.AppendLine();

        text.AppendLine("## The paper's table 9 beside ours (N = 4)");
        text.AppendLine();
        text.AppendLine("| oracle | qubits | gates | depth | basis |");
        text.AppendLine("|---|---:|---:|---:|---|");
        text.AppendLine($"| paper (Qiskit) | {PaperQubits} | {PaperGates} | {PaperDepth} | Qiskit's, after its decomposition (not stated further) |");
        foreach (var construction in new[] { OracleConstruction.Baseline, OracleConstruction.Compact, OracleConstruction.Narrow })
        {
            if (!points.TryGetValue((4, c4, construction.Name), out var p)) continue;
            if (p.Counts is { } counts)
            {
                text.AppendLine($"| ours, {construction} | {p.Logical.Qubits} | {counts.Native.GateCount} | {counts.Native.Depth} | QDK intrinsics (CCX is one gate) |");
                text.AppendLine($"| ours, {construction} | {p.Logical.Qubits} | {counts.QiskitCcx.GateCount} | {counts.QiskitCcx.Depth} | CCX as Qiskit's 15 Clifford+T gates |");
            }
            else text.AppendLine($"| ours, {construction} | {p.Logical.Qubits} | – | – | (circuit not extracted) |");
        }
        text.AppendLine();
        text.AppendLine("How the bases differ. The QDK's circuit is the trace of the simulator's intrinsic gates: X, H, S, T, rotations, CX, CZ and");
        text.AppendLine("CCX (a Toffoli is one gate), with measurements and resets listed apart. The standard library uncomputes every AND and every");
        text.AppendLine("table lookup by measurement: an X-basis measurement and, on some outcomes, a CZ or Z, where a unitary circuit (as Qiskit's");
        text.AppendLine("multi-controlled gates build) spends a second Toffoli. Qiskit reports counts after decomposing to its basis, typically single-");
        text.AppendLine("qubit gates and CX, where a Toffoli is 15 gates (2 H, 6 CX, 7 T/T†) and depth 11; the second row of each of ours replaces");
        text.AppendLine("every CCX by exactly that definition, which is the closer comparison, though Qiskit's transpiler would also merge adjacent");
        text.AppendLine("single-qubit gates. Qubits are not basis-dependent: ours count the peak in use, the standard library's auxiliary qubits");
        text.AppendLine("(lookup helpers, comparator carries, the unlookup's power products) included.");
        text.AppendLine();

        text.AppendLine($"## The oracle against the number of primitives ({c4}-bit grid), before → after");
        text.AppendLine();
        text.AppendLine($"Before: `{OracleConstruction.Baseline}`, the oracle as first built (commit 97cb017; the same circuit, kept as `--oracle baseline`): x, y and z");
        text.AppendLine("tested for every primitive, minimum then maximum in one register, so 6 lookups and an unlookup per computation. After:");
        text.AppendLine($"`{OracleConstruction.Compact}`, the default: only the two axes in each primitive's plane (on the flat axis the point is the plane and");
        text.AppendLine("min = max, so that test always passes) and both bounds loaded at once, so 2 lookups and an unlookup, for one more coordinate");
        text.AppendLine("register and one flag fewer. Every construction is checked against verify-rpc on every basis state (`GateOracleTests`).");
        text.AppendLine();
        SweepTable(text, "N", primitives.Select(n => (n.ToString(CultureInfo.InvariantCulture), (n, c4))), withCircuits);

        text.AppendLine($"## The oracle against the coordinate bits (N = {EstimateSweep.DefaultPrimitives}), before → after");
        text.AppendLine();
        SweepTable(text, "bits", bits.Select(c => (c.ToString(CultureInfo.InvariantCulture), (EstimateSweep.DefaultPrimitives, c))), withCircuits);

        text.AppendLine("## Unload by measurement or by lookup");
        text.AppendLine();
        text.AppendLine("Both constructions above clear the loaded registers with the standard library's measurement-based unlookup (`Adjoint Select`:");
        text.AppendLine("X-basis measurements, then a phase lookup over the index register built from power products, which needs");
        text.AppendLine("2^⌊n/2⌋ + 2^⌈n/2⌉ − n − 2 auxiliary qubits). Unloading with a second lookup of the same data instead (`narrow` is `compact` so built)");
        text.AppendLine("needs only the lookup's n − 1 helpers but a lookup's Toffolis. Figures are measured → lookup.");
        text.AppendLine();
        text.AppendLine("| N | " + string.Join(" | ", UnloadPairs.Select(p => $"{p.Measured}: qubits | CCZ | CCZ change")) + " |");
        text.AppendLine("|---:|" + string.Concat(UnloadPairs.Select(_ => "---:|---:|---:|")));
        foreach (var n in primitives)
        {
            var cells = new List<string>();
            foreach (var (measured, lookup) in UnloadPairs)
            {
                if (points.TryGetValue((n, c4, measured.Name), out var m) && points.TryGetValue((n, c4, lookup.Name), out var l))
                    cells.Add($"{Arrow(m.Logical.Qubits, l.Logical.Qubits)} | {Arrow(m.Logical.Ccz, l.Logical.Ccz)} | {Change(m.Logical.Ccz, l.Logical.Ccz)}");
                else cells.Add("– | – | –");
            }
            text.AppendLine($"| {n} | {string.Join(" | ", cells)} |");
        }
        text.AppendLine();
        text.AppendLine("The unlookup's power products set the peak width from N = 32 on; the lookup keeps it at the registers plus n − 1. The Toffoli");
        text.AppendLine("price of the lookup is the same two extra lookups per oracle call in both constructions, so it weighs more, relative to the");
        text.AppendLine("rest, in the compact one, which has fewer lookups to begin with.");
        text.AppendLine();

        text.AppendLine("## Each change on its own");
        text.AppendLine();
        text.AppendLine("| N | construction | axes | bound registers | qubits | CCZ | measurements |" + (withCircuits ? " gates (QDK) | depth (QDK) |" : ""));
        text.AppendLine("|---:|---|---:|---:|---:|---:|---:|" + (withCircuits ? "---:|---:|" : ""));
        foreach (var n in ablation)
            foreach (var construction in Ablation)
            {
                if (!points.TryGetValue((n, c4, construction.Name), out var p)) continue;
                var circuit = p.Counts is { } counts ? $" {counts.Native.GateCount} | {counts.Native.Depth} |" : withCircuits ? " – | – |" : "";
                text.AppendLine($"| {n} | {construction} | {construction.Axes} | {construction.BoundRegisters} | {p.Logical.Qubits} | {p.Logical.Ccz} | {p.Logical.Measurements} |{circuit}");
            }
        text.AppendLine();

        text.AppendLine($"## Physical estimates ({OracleConstruction.Compact}, {c4}-bit grid)");
        text.AppendLine();
        text.AppendLine("| N | " + string.Join(" | ", models.Select(m => $"{m}: physical qubits | runtime | code distance")) + " |");
        text.AppendLine("|---:|" + string.Concat(models.Select(_ => "---:|---:|---:|")));
        foreach (var n in primitives)
        {
            if (!points.TryGetValue((n, c4, OracleConstruction.Compact.Name), out var p)) continue;
            text.AppendLine($"| {n} | " + string.Join(" | ", p.Physical.Select(e => $"{e.PhysicalQubits} | {EstimateTable.Duration(e.RuntimeNanoseconds)} | {e.CodeDistance}")) + " |");
        }
        text.AppendLine();

        if (plots.Count > 0)
        {
            text.AppendLine("## Plots");
            text.AppendLine();
            foreach (var (file, caption) in plots) text.AppendLine($"{caption}:").AppendLine().AppendLine($"![{caption}]({file})").AppendLine();
        }

        text.AppendLine("## Conventions");
        text.AppendLine();
        foreach (var note in EstimateTable.Conventions(withCircuits)) text.AppendLine($"- {note}");
        text.AppendLine("- \"a → b\": the baseline construction's figure, then the compact one's, on the same ray.");
        return text.ToString();
    }

    private void SweepTable(StringBuilder text, string key, IEnumerable<(string Label, (int Primitives, int Bits) Point)> rows, bool withCircuits)
    {
        text.AppendLine($"| {key} | depth bits | qubits | ancillas | CCZ | measurements |" + (withCircuits ? " gates (QDK) | depth (QDK) | gates (CCX as 15) | depth (CCX as 15) |" : ""));
        text.AppendLine("|---:|---:|---:|---:|---:|---:|" + (withCircuits ? "---:|---:|---:|---:|" : ""));
        foreach (var (label, (n, c)) in rows)
        {
            if (!points.TryGetValue((n, c, OracleConstruction.Baseline.Name), out var b) || !points.TryGetValue((n, c, OracleConstruction.Compact.Name), out var a)) continue;
            var line = $"| {label} | {a.Subject.Oracle.Table.DepthBits} | {Arrow(b.Logical.Qubits, a.Logical.Qubits)} | {Arrow(b.Registers!.Value.AncillaQubits, a.Registers!.Value.AncillaQubits)} | {Arrow(b.Logical.Ccz, a.Logical.Ccz)} | {Arrow(b.Logical.Measurements, a.Logical.Measurements)} |";
            if (withCircuits && b.Counts is { } bc && a.Counts is { } ac)
                line += $" {Arrow(bc.Native.GateCount, ac.Native.GateCount)} | {Arrow(bc.Native.Depth, ac.Native.Depth)} | {Arrow(bc.QiskitCcx.GateCount, ac.QiskitCcx.GateCount)} | {Arrow(bc.QiskitCcx.Depth, ac.QiskitCcx.Depth)} |";
            text.AppendLine(line);
        }
        text.AppendLine();
    }

    private static string Arrow(long before, long after) => $"{before} → {after}";

    private static string Change(long before, long after) =>
        before == 0 ? "–" : ((after - before) / (double)before).ToString("+0%;-0%;0%", CultureInfo.InvariantCulture);
}
