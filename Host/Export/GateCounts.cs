namespace QuantumRayTracing.Export;

/// <summary>
/// A circuit's gates by name as written (each gate of a feedback branch counted once, whether or not it
/// would run), its measurements and its feedback branches.
/// </summary>
public sealed record GateCounts(IReadOnlyDictionary<string, int> Gates, int Measurements, int Conditionals)
{
    public int TotalGates => Gates.Values.Sum();

    public static GateCounts Of(QirCircuit circuit)
    {
        var gates = new SortedDictionary<string, int>(StringComparer.Ordinal);
        var (measurements, conditionals) = (0, 0);
        void Count(GateStep gate) => gates[gate.Gate] = gates.GetValueOrDefault(gate.Gate) + 1;
        foreach (var step in circuit.Steps)
        {
            switch (step)
            {
                case GateStep gate: Count(gate); break;
                case MeasureStep: measurements++; break;
                case ConditionalStep branch:
                    conditionals++;
                    foreach (var gate in branch.Gates) Count(gate);
                    break;
            }
        }
        return new GateCounts(gates, measurements, conditionals);
    }

    /// <summary>"1234 gates (ccx 61, cx 343, ...), 3 measurements, 0 feedback branches".</summary>
    public override string ToString() =>
        $"{ExportHeader.Plural(TotalGates, "gate")} ({string.Join(", ", Gates.Select(g => $"{g.Key} {g.Value}"))}), {ExportHeader.Plural(Measurements, "measurement")}, {ExportHeader.Plural(Conditionals, "feedback branch", "feedback branches")}";
}
