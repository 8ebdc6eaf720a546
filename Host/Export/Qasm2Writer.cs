using System.Text;

namespace QuantumRayTracing.Export;

/// <summary>
/// Writes a unitary circuit (<see cref="UnitaryUncomputation"/>) as OpenQASM 2.0 on qelib1.inc: one quantum
/// register q, the measured register as a classical register of the export's name, measured at the end.
/// Measured qubits are not reused afterwards, so the measure-and-reset of QIR's mresetz becomes a measure.
/// </summary>
public static class Qasm2Writer
{
    public static string Write(QirCircuit circuit, string header, string registerName)
    {
        var text = new StringBuilder(header);
        text.Append("OPENQASM 2.0;\ninclude \"qelib1.inc\";\n");
        text.Append($"qreg q[{circuit.Qubits}];\ncreg {registerName}[{circuit.Outputs.Count}];\n");
        foreach (var step in circuit.Steps)
        {
            text.Append(step switch
            {
                GateStep gate => QasmGate.Statement(gate, "q"),
                MeasureStep m => $"measure q[{m.Qubit}] -> {registerName}[{MeasuredBit(circuit, m)}];",
                _ => throw new InvalidOperationException("OpenQASM 2 takes a unitary circuit; apply UnitaryUncomputation first"),
            }).Append('\n');
        }
        return text.ToString();
    }

    /// <summary>The register bit a final measurement fills: its result's place among the outputs.</summary>
    public static int MeasuredBit(QirCircuit circuit, MeasureStep measure)
    {
        var bit = circuit.Outputs.ToList().IndexOf(measure.Result);
        return bit >= 0 ? bit : throw new InvalidOperationException($"result {measure.Result} is not an output");
    }
}
