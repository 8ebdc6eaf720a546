namespace QuantumRayTracing.Export;

/// <summary>
/// A circuit as the QDK compiled it to QIR: <see cref="Qubits"/> qubits, its steps in order, and the result
/// slots the program outputs, in output order (the measured register's bit 0 first).
/// </summary>
public sealed record QirCircuit(int Qubits, IReadOnlyList<CircuitStep> Steps, IReadOnlyList<int> Outputs);
