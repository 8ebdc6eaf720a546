namespace QuantumRayTracing.Search;

/// <summary>
/// The qubits one Grover search over N indices holds: ceil(log2 N) index qubits and the auxiliaries of
/// the phase on the all-ones state (Q# <c>ApplyPhaseToAllOnes</c>: n − 2 for n ≥ 3 index qubits),
/// allocated once per search and returned clean after every gate. The phase oracle needs no flag qubit.
/// </summary>
public readonly record struct SearchRegisters(int IndexQubits, int AuxiliaryQubits)
{
    public static SearchRegisters For(int count)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(count, 1);
        var index = 32 - int.LeadingZeroCount(count - 1);
        // A Toffoli ladder over n qubits ANDs the first n − 1 into n − 2 auxiliaries.
        return new SearchRegisters(index, Math.Max(0, index - 2));
    }

    /// <summary>Peak qubits in use, auxiliaries included.</summary>
    public int PeakQubits => IndexQubits + AuxiliaryQubits;
}
