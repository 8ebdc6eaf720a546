using System.Text;

namespace QuantumRayTracing.Export;

/// <summary>The comment lines an exported file starts with ("// " for OpenQASM, "; " for QIR).</summary>
public static class ExportHeader
{
    public static string Write(ExportSubject subject, ExportFormat format, QirCircuit circuit, IdealDistribution ideal)
    {
        var prefix = format == ExportFormat.Qir ? "; " : "// ";
        var text = new StringBuilder();
        void Line(string line) => text.Append(prefix).Append(line).Append('\n');
        Line($"QuantumRayTracing: {subject.Title}");
        foreach (var line in subject.Description) Line(line);
        var counts = GateCounts.Of(circuit);
        Line(Form(format, counts.Conditionals));
        Line($"qubits: {circuit.Qubits}; {counts}{(format == ExportFormat.Qasm2 ? "" : " (a branch's gates counted once whether or not they run)")}; "
            + $"depth {CircuitDepth.Of(circuit)}{(counts.Conditionals == 0 ? "" : " with every branch taken")}");
        Line($"measured register: {subject.RegisterName}, {Plural(subject.RegisterQubits, "bit")}, bit 0 least significant");
        Line(ideal.Line);
        if (ideal.Remainder is { } rest) Line(rest);
        return text.ToString();
    }

    /// <summary>The form line: how the file uncomputes, from the circuit as written (<paramref name="branches"/> feedback branches).</summary>
    private static string Form(ExportFormat format, int branches)
    {
        if (format == ExportFormat.Qasm2)
            return "form: unitary; every uncomputation by gates (OpenQASM 2 has no mid-circuit feedback): each AND the QDK's program uncomputes by measurement and feedback is a Toffoli here";
        var (what, output) = format == ExportFormat.Qasm3
            ? ("the QDK's program", "the register measured at the end")
            : ("the QDK's QIR, adaptive profile", "the register's results recorded as the output");
        var rest = branches == 0
            ? "every uncomputation by gates, no mid-circuit measurement"
            : $"the ANDs it uncomputes by measurement kept so: measurement, reset and feedback{(format == ExportFormat.Qasm3 ? " (bit uncompute)" : "")}, {Plural(branches, "branch", "branches")}";
        return $"form: {what}; {rest}; {output}";
    }

    /// <summary>"1 bit", "3 bits"; <paramref name="many"/> for nouns that do not just add an s.</summary>
    public static string Plural(int count, string one, string? many = null) => $"{count} {(count == 1 ? one : many ?? one + "s")}";
}
