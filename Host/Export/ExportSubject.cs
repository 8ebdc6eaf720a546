namespace QuantumRayTracing.Export;

/// <summary>
/// What one export writes: a Q# operation applied to a fresh register of <see cref="RegisterQubits"/> +
/// <see cref="UnmeasuredQubits"/> qubits (<see cref="Apply"/>, a <c>Qubit[] =&gt; Unit</c> expression), the
/// first <see cref="RegisterQubits"/> measured at the end into the classical register <see cref="RegisterName"/>,
/// and the lines that say what it is (scene, ray, construction, ...), written into the file's header. The
/// unmeasured qubits (QSS's coin register, entangled with its counter) are left as the circuit leaves them.
/// <see cref="UnitaryApply"/>, when given, is the same circuit with fewer of its uncomputations by measurement
/// (the rest by gates), for formats without feedback: the QDK's QIR compile time grows with the square of the
/// number of feedback branches.
/// </summary>
public sealed record ExportSubject(string Title, IReadOnlyList<string> Description, string Apply, int RegisterQubits, string RegisterName, int UnmeasuredQubits = 0, string? UnitaryApply = null)
{
    /// <summary>The expression the export of <paramref name="format"/> compiles.</summary>
    public string ApplyFor(ExportFormat format) => format == ExportFormat.Qasm2 && UnitaryApply is { } unitary ? unitary : Apply;
}
