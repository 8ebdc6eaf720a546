using QuantumRayTracing.Intersection;
using QuantumRayTracing.Output;

namespace QuantumRayTracing.Estimates;

/// <summary>The PNG plots of a resource sweep: Toffolis, qubits and gates against N and against the coordinate bits.</summary>
public static class SweepPlots
{
    /// <summary>One plot: the file name's suffix (estimates-&lt;suffix&gt;.png beside the report), its caption and what it draws.</summary>
    public sealed record Plot(string Suffix, string Caption, PlotSpec Spec);

    public static IReadOnlyList<Plot> Draw(SweepReport report, IReadOnlyList<int> primitives, IReadOnlyList<int> bits)
    {
        var plots = new List<Plot>();
        var c = EstimateSweep.DefaultCoordinateBits;
        var n = EstimateSweep.DefaultPrimitives;
        var measured = new[] { OracleConstruction.Baseline, OracleConstruction.Compact, OracleConstruction.Narrow };
        var beforeAfter = new[] { OracleConstruction.Baseline, OracleConstruction.Compact };
        var withCircuits = report.Points.Values.All(p => p.Counts is not null);

        PlotSeries ByN(OracleConstruction k, string label, Func<CircuitEstimate, double> value) =>
            new(label, primitives.Where(p => report.Points.ContainsKey((p, c, k.Name))).Select(p => ((double)p, value(report.Points[(p, c, k.Name)]))).ToArray());
        PlotSeries ByBits(OracleConstruction k, string label, Func<CircuitEstimate, double> value) =>
            new(label, bits.Where(b => report.Points.ContainsKey((n, b, k.Name))).Select(b => ((double)b, value(report.Points[(n, b, k.Name)]))).ToArray());
        void Add(string suffix, string caption, PlotSpec spec)
        {
            if (spec.Series.Any(s => s.Points.Count > 0)) plots.Add(new Plot(suffix, caption, spec));
        }

        Add("ccz-vs-primitives", $"Toffolis (CCZ) of one oracle call against N, {c}-bit grid",
            new PlotSpec($"Oracle Toffolis against primitives ({c}-bit grid)", "primitives N", "CCZ (Resource Estimator)", AxisScale.Log10, AxisScale.Log10,
                measured.Select(k => ByN(k, k.Name, e => e.Logical.Ccz)).ToArray()));
        Add("qubits-vs-primitives", $"Peak logical qubits of the oracle against N, {c}-bit grid: the measured unload's power products grow as about 2 sqrt(N)",
            new PlotSpec($"Oracle width against primitives ({c}-bit grid)", "primitives N", "peak logical qubits", AxisScale.Log10, AxisScale.Linear,
                measured.Select(k => ByN(k, k.Name, e => e.Logical.Qubits)).ToArray()));
        if (withCircuits)
        {
            var series = beforeAfter.SelectMany(k => new[]
            {
                ByN(k, $"{k.Name}, QDK gates", e => e.Counts!.Native.GateCount),
                ByN(k, $"{k.Name}, CCX as 15", e => e.Counts!.QiskitCcx.GateCount),
            }).Append(new PlotSeries("paper table 9 (Qiskit)", [(4.0, SweepReport.PaperGates)], Lines: false)).ToArray();
            Add("gates-vs-primitives", $"Gates of one oracle call against N, {c}-bit grid, in the QDK's gates and with each CCX as Qiskit's 15; the paper's table 9 at N = 4",
                new PlotSpec($"Oracle gates against primitives ({c}-bit grid)", "primitives N", "gates", AxisScale.Log10, AxisScale.Log10, series));
        }
        Add("qubits-vs-bits", $"Peak logical qubits of the oracle against the coordinate bits, N = {n}",
            new PlotSpec($"Oracle width against coordinate bits (N = {n})", "coordinate bits", "peak logical qubits", AxisScale.Linear, AxisScale.Linear,
                beforeAfter.Select(k => ByBits(k, k.Name, e => e.Logical.Qubits)).ToArray()));
        if (withCircuits)
            Add("gates-vs-bits", $"Gates (QDK basis) of one oracle call against the coordinate bits, N = {n}",
                new PlotSpec($"Oracle gates against coordinate bits (N = {n})", "coordinate bits", "gates (QDK basis)", AxisScale.Linear, AxisScale.Linear,
                    beforeAfter.Select(k => ByBits(k, k.Name, e => e.Counts!.Native.GateCount)).ToArray()));
        return plots;
    }
}
