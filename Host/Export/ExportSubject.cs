namespace QuantumRayTracing.Export;

/// <summary>
/// What one export writes: a Q# operation applied to a fresh register of <see cref="RegisterQubits"/>
/// qubits (<see cref="Apply"/>, a <c>Qubit[] =&gt; Unit</c> expression), the register measured at the
/// end into the classical register <see cref="RegisterName"/>, and the lines that say what it is
/// (scene, ray, construction, ...), written into the file's header.
/// </summary>
public sealed record ExportSubject(string Title, IReadOnlyList<string> Description, string Apply, int RegisterQubits, string RegisterName);
