namespace QuantumRayTracing.Search {
    import Std.Arrays.Mapped;
    import Std.Arrays.IsEmpty;

    /// # Summary
    /// The marking oracle's first construction, kept as the reference of `ApplyMarkingOracle` and
    /// for benchmarks: a Z on a flag qubit in |1⟩ for every marked index, controlled by the index
    /// register through the standard library's multi-controlled Z.
    ///
    /// # Input
    /// ## marked
    /// Distinct indices to mark, each below 2^Length(index).
    /// ## index
    /// Little-endian index register.
    /// ## flag
    /// A qubit held in |1⟩, so that each controlled Z kicks its phase back; it stays in |1⟩.
    ///
    /// # Remarks
    /// The standard library's `Controlled Z` allocates and releases n − 2 auxiliaries inside every
    /// gate, which costs the simulator more than the gates; `ApplyMarkingOracle` reuses its own.
    internal operation ApplyMarkingOracleWithControlledZ(marked : Int[], index : Qubit[], flag : Qubit) : Unit is Adj + Ctl {
        if not IsEmpty(marked) {
            let allOnes = (1 <<< Length(index)) - 1;
            let flips = Mapped(m -> allOnes ^^^ m, marked);
            for k in 0..Length(flips) - 1 {
                let previous = k == 0 ? 0 | flips[k - 1];
                ApplyXorInPlace(previous ^^^ flips[k], index);
                Controlled Z(index, flag);
            }
            ApplyXorInPlace(flips[Length(flips) - 1], index);
        }
    }
}
