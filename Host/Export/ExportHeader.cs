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
        Line(format switch
        {
            ExportFormat.Qasm2 => "form: unitary; every uncomputation by gates (OpenQASM 2 has no mid-circuit feedback): each measurement-based AND uncomputation of the QDK's program is a Toffoli here",
            ExportFormat.Qasm3 => "form: the QDK's program; AND uncomputations by measurement and feedback (bit uncompute), the register measured at the end",
            _ => "form: the QDK's QIR, adaptive profile; AND uncomputations by measurement and feedback, the register's results recorded as the output",
        });
        Line($"qubits: {circuit.Qubits}; {GateCounts.Of(circuit)}{(format == ExportFormat.Qasm2 ? "" : " (a branch's gates counted once whether or not they run)")}");
        Line($"measured register: {subject.RegisterName}, {Plural(subject.RegisterQubits, "bit")}, bit 0 least significant");
        Line(ideal.Line);
        if (ideal.Remainder is { } rest) Line(rest);
        return text.ToString();
    }

    /// <summary>"1 bit", "3 bits"; <paramref name="many"/> for nouns that do not just add an s.</summary>
    public static string Plural(int count, string one, string? many = null) => $"{count} {(count == 1 ? one : many ?? one + "s")}";
}
