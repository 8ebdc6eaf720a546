namespace QuantumRayTracing.Search {
    import Std.Math.BitSizeI;
    import QuantumRayTracing.Supersampling.SetDepolarizingRate;

    /// # Summary
    /// `MeasureGroverSearch` under a device noise model: the same gates in the same order (H on every index qubit,
    /// then per iteration the lookup oracle's X toggles and all-ones phases and the reflection's H, X, phase, X, H),
    /// each followed by depolarizing noise at its own rate, and the index measured with the noise off: the host
    /// applies the readout error to the measured bits.
    ///
    /// # Input
    /// ## oneQubit
    /// Depolarizing probability after each one-qubit gate (H, X, Z).
    /// ## twoQubit
    /// Depolarizing probability on each qubit after each gate on two or more qubits (CZ, CCNOT).
    /// ## count
    /// Number of indices searched: a power of two.
    /// ## marked
    /// Distinct marked indices, each in 0..count-1.
    /// ## iterations
    /// Number of Grover iterations r ≥ 0.
    ///
    /// # Output
    /// The measured index, before any readout error.
    ///
    /// # Remarks
    /// Only N a power of two: there the uniform preparation is one H per qubit. Otherwise it holds controlled
    /// rotations and controlled H gates that the standard library decomposes into gates of mixed arity, whose
    /// rates could not be set one by one. The gates are called through device helpers rather than the ideal
    /// operations because Q#'s generated adjoints run the rate-setting function calls ahead of the gates.
    internal operation MeasureGroverSearchOnDevice(oneQubit : Double, twoQubit : Double, count : Int, marked : Int[], iterations : Int) : Int {
        CheckGroverSearch(count, marked, iterations);
        if count &&& (count - 1) != 0 {
            fail $"the device search runs N a power of two (its preparation is one H per qubit), got N = {count}";
        }
        let oracleSet = 2 * Length(marked) > count ? ComplementIndices(count, marked) | marked;
        use index = Qubit[BitSizeI(count - 1)];
        use auxiliaries = Qubit[PhaseAuxiliaryCount(Length(index))];
        let allOnes = (1 <<< Length(index)) - 1;
        ApplyToEach(ApplyOneQubitGateOnDevice(oneQubit, H, _), index);
        for _ in 1..iterations {
            // The lookup oracle (ApplyMarkingOracle): toggle to each marked value's flip pattern, phase the all-ones state.
            mutable previous = 0;
            for m in oracleSet {
                ApplyXorInPlaceOnDevice(oneQubit, previous ^^^ (allOnes ^^^ m), index);
                ApplyPhaseToAllOnesOnDevice(oneQubit, twoQubit, index, auxiliaries);
                set previous = allOnes ^^^ m;
            }
            ApplyXorInPlaceOnDevice(oneQubit, previous, index);
            // The reflection about the uniform superposition (ReflectAboutUniformSuperposition).
            ApplyToEach(ApplyOneQubitGateOnDevice(oneQubit, H, _), index);
            ApplyXorInPlaceOnDevice(oneQubit, allOnes, index);
            ApplyPhaseToAllOnesOnDevice(oneQubit, twoQubit, index, auxiliaries);
            ApplyXorInPlaceOnDevice(oneQubit, allOnes, index);
            ApplyToEach(ApplyOneQubitGateOnDevice(oneQubit, H, _), index);
        }
        SetDepolarizingRate(0.0);
        // Noise can leave an auxiliary in |1⟩; it is reset, as a device would, before it is released.
        ResetAll(auxiliaries);
        MeasureIntegerReadingLossAsZero(index)
    }
}
