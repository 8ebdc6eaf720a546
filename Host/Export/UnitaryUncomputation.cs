namespace QuantumRayTracing.Export;

/// <summary>
/// Turns a circuit whose only mid-circuit measurements are the standard library's measurement-based
/// uncomputation of AND into a unitary one, for formats without feedback (OpenQASM 2). The library's
/// <c>Adjoint AND(a, b, t)</c>, with t = a ∧ b, is H(t), measure-and-reset t, and CZ(a, b) when the result
/// is One; a Toffoli CCX(a, b, t) returns t to |0⟩ the same way, by gates. Any other mid-circuit
/// measurement is refused.
/// </summary>
public static class UnitaryUncomputation
{
    public static QirCircuit Apply(QirCircuit circuit)
    {
        var outputs = circuit.Outputs.ToHashSet();
        var steps = new List<CircuitStep>();
        var source = circuit.Steps;
        for (var k = 0; k < source.Count; k++)
        {
            if (source[k] is MeasureStep measure && !outputs.Contains(measure.Result))
            {
                var gate = k > 0 ? source[k - 1] as GateStep : null;
                var feedback = k + 1 < source.Count ? source[k + 1] as ConditionalStep : null;
                if (gate is not { Gate: "h" } || gate.Qubits[0] != measure.Qubit || steps[^1] != gate
                    || feedback is not { Gates: [{ Gate: "cz", Qubits: [var a, var b] }] } || feedback.Result != measure.Result)
                    throw new InvalidOperationException($"step {k}: a mid-circuit measurement of qubit {measure.Qubit} that is not an AND's uncomputation has no unitary form");
                steps[^1] = new GateStep("ccx", [a, b, measure.Qubit]);
                k++;
                continue;
            }
            if (source[k] is ConditionalStep) throw new InvalidOperationException($"step {k}: feedback without its AND uncomputation has no unitary form");
            steps.Add(source[k]);
        }
        return circuit with { Steps = steps };
    }
}
