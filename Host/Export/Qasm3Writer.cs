using System.Text;

namespace QuantumRayTracing.Export;

/// <summary>
/// Writes a circuit as OpenQASM 3.0 on stdgates.inc, keeping its measurement-based uncomputation: a
/// mid-circuit measurement goes into the bit <c>uncompute</c>, the qubit is reset, and the feedback gates
/// run under <c>if (uncompute)</c>. The measured register is a bit register of the export's name.
/// </summary>
public static class Qasm3Writer
{
    public static string Write(QirCircuit circuit, string header, string registerName)
    {
        var outputs = circuit.Outputs.ToHashSet();
        var text = new StringBuilder(header);
        text.Append("OPENQASM 3.0;\ninclude \"stdgates.inc\";\n");
        text.Append($"qubit[{circuit.Qubits}] q;\nbit[{circuit.Outputs.Count}] {registerName};\n");
        if (circuit.Steps.Any(s => s is MeasureStep m && !outputs.Contains(m.Result))) text.Append("bit uncompute;\n");
        int? held = null; // the result the bit uncompute holds
        foreach (var step in circuit.Steps)
        {
            switch (step)
            {
                case GateStep gate:
                    text.Append(QasmGate.Statement(gate, "q")).Append('\n');
                    break;
                case MeasureStep m when outputs.Contains(m.Result):
                    text.Append($"{registerName}[{Qasm2Writer.MeasuredBit(circuit, m)}] = measure q[{m.Qubit}];\n");
                    break;
                case MeasureStep m:
                    text.Append($"uncompute = measure q[{m.Qubit}];\nreset q[{m.Qubit}];\n");
                    held = m.Result;
                    break;
                case ConditionalStep branch:
                    if (branch.Result != held) throw new InvalidOperationException($"feedback on result {branch.Result}, which is not the last mid-circuit measurement");
                    text.Append("if (uncompute) {");
                    foreach (var gate in branch.Gates) text.Append(' ').Append(QasmGate.Statement(gate, "q"));
                    text.Append(" }\n");
                    break;
            }
        }
        return text.ToString();
    }
}
