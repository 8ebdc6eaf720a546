using System.Globalization;

namespace QuantumRayTracing.Export;

/// <summary>
/// One gate as an OpenQASM statement. OpenQASM 2's qelib1.inc and OpenQASM 3's stdgates.inc name our gates
/// alike (x, h, sdg, tdg, cx, cz, ccx, ry, ...), so both writers share it. Angles are written with
/// round-trip precision, so the file holds the QDK's doubles exactly.
/// </summary>
public static class QasmGate
{
    public static string Statement(GateStep gate, string register)
    {
        var operands = string.Join(", ", gate.Qubits.Select(q => $"{register}[{q.ToString(CultureInfo.InvariantCulture)}]"));
        var angle = gate.Angle is { } a ? $"({a.ToString("R", CultureInfo.InvariantCulture)})" : "";
        return $"{gate.Gate}{angle} {operands};";
    }
}
