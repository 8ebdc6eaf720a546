namespace QuantumRayTracing.Search;

/// <summary>
/// The qubits one Grover search over N indices holds: ceil(log2 N) index qubits, one oracle flag,
/// and the auxiliary qubits the standard library's multi-controlled Z borrows inside each gate
/// (n − 2 for n ≥ 3 controls, released clean after the gate).
/// </summary>
public readonly record struct SearchRegisters(int IndexQubits, int FlagQubits, int AuxiliaryQubits)
{
    public static SearchRegisters For(int count)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(count, 1);
        var index = 32 - int.LeadingZeroCount(count - 1);
        // Controlled Z(index, flag) has `index` controls; Std allocates controls − 2 auxiliaries past two.
        return new SearchRegisters(index, 1, Math.Max(0, index - 2));
    }

    /// <summary>Qubits allocated by the search's own registers.</summary>
    public int RegisterQubits => IndexQubits + FlagQubits;

    /// <summary>Peak qubits in use, auxiliaries included.</summary>
    public int PeakQubits => RegisterQubits + AuxiliaryQubits;
}
