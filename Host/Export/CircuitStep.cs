namespace QuantumRayTracing.Export;

/// <summary>One step of a circuit read from QIR, in program order.</summary>
public abstract record CircuitStep;

/// <summary>
/// A gate on <see cref="Qubits"/> (controls first, then the target), named as OpenQASM's standard gates
/// name it (x, h, sdg, cx, ccx, ry, ...); <see cref="Angle"/> for the rotations.
/// </summary>
public sealed record GateStep(string Gate, IReadOnlyList<int> Qubits, double? Angle = null) : CircuitStep;

/// <summary>A Z-basis measurement of a qubit into result slot <see cref="Result"/>, after which the qubit is reset to |0⟩ (QIR's mresetz).</summary>
public sealed record MeasureStep(int Qubit, int Result) : CircuitStep;

/// <summary>Gates applied only when result slot <see cref="Result"/> read One: the feedback of a measurement-based uncomputation.</summary>
public sealed record ConditionalStep(int Result, IReadOnlyList<GateStep> Gates) : CircuitStep;
