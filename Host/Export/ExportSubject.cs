namespace QuantumRayTracing.Export;

/// <summary>
/// What one export writes: a Q# operation applied to a fresh register of <see cref="RegisterQubits"/> +
/// <see cref="UnmeasuredQubits"/> qubits (<see cref="Apply"/>, a <c>Qubit[] =&gt; Unit</c> expression), the
/// first <see cref="RegisterQubits"/> measured at the end into the classical register <see cref="RegisterName"/>,
/// and the lines that say what it is (scene, ray, construction, how its lookups uncompute, ...), written into
/// the file's header. The unmeasured qubits (QSS's coin register, entangled with its counter) are left as the
/// circuit leaves them.
/// </summary>
public sealed record ExportSubject(string Title, IReadOnlyList<string> Description, string Apply, int RegisterQubits, string RegisterName, int UnmeasuredQubits = 0);
