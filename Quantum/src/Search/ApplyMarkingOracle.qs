namespace QuantumRayTracing.Search {
    import Std.Arrays.Mapped;
    import Std.Arrays.IsEmpty;

    /// # Summary
    /// Applies a phase of −1 to every index in `marked`: the lookup-table oracle, whose marked
    /// set the host computes from the ray's classical table.
    ///
    /// # Input
    /// ## gates
    /// The gates to write it in: `IdealLookupGates()`, or `DeviceLookupGates` under a device noise model.
    /// ## marked
    /// Distinct indices to mark, each below 2^Length(index).
    /// ## index
    /// Little-endian index register.
    /// ## auxiliaries
    /// `PhaseAuxiliaryCount(Length(index))` qubits in |0⟩, for `ApplyPhaseToAllOnes`; they end in |0⟩.
    ///
    /// # Remarks
    /// The phase oracle directly, rather than a bit-flip oracle with its output in |−⟩: the state
    /// has 2^n amplitudes and no output qubit. Each marked value m is matched by flipping the
    /// index bits where m is 0 and applying a phase to the all-ones state; between consecutive
    /// marked values only the bits whose flip pattern changes are toggled, which removes most X
    /// gates when the set is sorted.
    internal operation ApplyMarkingOracle(gates : LookupGates, marked : Int[], index : Qubit[], auxiliaries : Qubit[]) : Unit is Adj + Ctl {
        if not IsEmpty(marked) {
            let allOnes = (1 <<< Length(index)) - 1;
            let flips = Mapped(m -> allOnes ^^^ m, marked);
            for k in 0..Length(flips) - 1 {
                let previous = k == 0 ? 0 | flips[k - 1];
                ApplyXorWith(gates.X, previous ^^^ flips[k], index);
                ApplyPhaseToAllOnes(gates, index, auxiliaries);
            }
            ApplyXorWith(gates.X, flips[Length(flips) - 1], index);
        }
    }
}
