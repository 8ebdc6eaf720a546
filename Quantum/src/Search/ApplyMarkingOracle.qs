namespace QuantumRayTracing.Search {
    import Std.Arrays.Mapped;
    import Std.Arrays.IsEmpty;

    /// # Summary
    /// Applies a phase of −1 to every index in `marked`, through a Z on `flag` controlled by the
    /// index register: the lookup-table oracle, whose marked set the host computes from the
    /// ray's classical table.
    ///
    /// # Input
    /// ## marked
    /// Distinct indices to mark, each below 2^Length(index).
    /// ## index
    /// Little-endian index register.
    /// ## flag
    /// Oracle output qubit, held in |1⟩ so that the controlled Z kicks its phase back.
    ///
    /// # Remarks
    /// This is the bit-flip oracle with its output in |−⟩, written with the output's H gates
    /// folded in (H X H = Z): the flag stays a basis state, so the simulated state has 2^n
    /// amplitudes, not 2^(n+1). Each marked value m is matched by flipping the index bits
    /// where m is 0; between consecutive marked values only the bits whose flip pattern
    /// changes are toggled, which removes most X gates when the set is sorted.
    operation ApplyMarkingOracle(marked : Int[], index : Qubit[], flag : Qubit) : Unit is Adj + Ctl {
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
