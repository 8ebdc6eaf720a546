namespace QuantumRayTracing.Export;

/// <summary>
/// A circuit's depth in its own gates: every step laid out as early as its qubits allow, each gate and each measurement one
/// layer. A feedback branch's gates wait for the measurement whose result they read and count as if they run, so for a file
/// with feedback it is the depth when every branch is taken.
/// </summary>
public static class CircuitDepth
{
    public static int Of(QirCircuit circuit)
    {
        ArgumentNullException.ThrowIfNull(circuit);
        var free = new int[circuit.Qubits]; // the first layer each qubit is free in
        var measured = new Dictionary<int, int>(); // result slot → the layer after its measurement
        var depth = 0;
        int Place(IReadOnlyList<int> qubits, int after)
        {
            var layer = qubits.Aggregate(after, (latest, q) => Math.Max(latest, free[q]));
            foreach (var q in qubits) free[q] = layer + 1;
            depth = Math.Max(depth, layer + 1);
            return layer + 1;
        }
        foreach (var step in circuit.Steps)
        {
            switch (step)
            {
                case GateStep gate: Place(gate.Qubits, 0); break;
                case MeasureStep measure: measured[measure.Result] = Place([measure.Qubit], 0); break;
                case ConditionalStep branch:
                    var after = measured.GetValueOrDefault(branch.Result);
                    foreach (var gate in branch.Gates) Place(gate.Qubits, after);
                    break;
            }
        }
        return depth;
    }
}
