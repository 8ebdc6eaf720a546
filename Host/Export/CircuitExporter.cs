using System.Text.Json.Nodes;
using QuantumRayTracing.Bridge;

namespace QuantumRayTracing.Export;

/// <summary>
/// Exports one circuit: the QDK compiles it to QIR (adaptive profile) and computes the measured register's
/// exact distribution (its marginal, when qubits are left unmeasured); OpenQASM is written from that QIR,
/// step for step (<see cref="QirReader"/>), so every format holds the QDK's circuit and its angles to the last bit.
/// </summary>
public static class CircuitExporter
{
    public static string Export(QSharpBridge bridge, ExportSubject subject, ExportFormat format)
    {
        var reply = bridge.Send(new JsonObject
        {
            ["method"] = "export",
            ["apply"] = subject.Apply,
            ["qubits"] = subject.RegisterQubits + subject.UnmeasuredQubits,
            ["measured"] = subject.RegisterQubits,
            ["profile"] = "adaptive_ri",
        }).AsObject();
        var qir = reply["qir"]!.GetValue<string>();
        var ideal = new IdealDistribution(reply["probabilities"]!.AsArray().Select(p => p!.GetValue<double>()).ToArray());
        var circuit = QirReader.Read(qir);
        if (circuit.Outputs.Count != subject.RegisterQubits)
            throw new InvalidOperationException($"the QIR outputs {circuit.Outputs.Count} results for a register of {subject.RegisterQubits} qubits");
        return format switch
        {
            ExportFormat.Qasm2 => Qasm2(subject, circuit, ideal),
            ExportFormat.Qasm3 => Qasm3Writer.Write(circuit, ExportHeader.Write(subject, format, circuit, ideal), subject.RegisterName),
            _ => ExportHeader.Write(subject, format, circuit, ideal) + qir,
        };
    }

    private static string Qasm2(ExportSubject subject, QirCircuit circuit, IdealDistribution ideal)
    {
        var unitary = UnitaryUncomputation.Apply(circuit);
        return Qasm2Writer.Write(unitary, ExportHeader.Write(subject, ExportFormat.Qasm2, unitary, ideal), subject.RegisterName);
    }
}
