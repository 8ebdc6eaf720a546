namespace QuantumRayTracing.Experiments;

/// <summary>What `bench simulator-capacity` measures: a dense state of each width in <paramref name="Qubits"/>, each in a fresh bridge.</summary>
public sealed record SimulatorCapacitySettings(IReadOnlyList<int> Qubits);
