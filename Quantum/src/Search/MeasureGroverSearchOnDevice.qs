namespace QuantumRayTracing.Search {
    import Std.Math.BitSizeI;
    import QuantumRayTracing.Supersampling.SetDepolarizingRate;

    /// # Summary
    /// `MeasureGroverSearch` under a device noise model: the same circuit (`ApplyGroverSearch`) in `DeviceLookupGates`,
    /// so every gate is followed by depolarizing noise at its own rate, and the index measured with the noise off: the
    /// host applies the readout error to the measured bits.
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
    /// rates could not be set one by one.
    internal operation MeasureGroverSearchOnDevice(oneQubit : Double, twoQubit : Double, count : Int, marked : Int[], iterations : Int) : Int {
        CheckGroverSearch(count, marked, iterations);
        use index = Qubit[BitSizeI(count - 1)];
        use auxiliaries = Qubit[PhaseAuxiliaryCount(Length(index))];
        ApplyGroverSearch(DeviceLookupGates(oneQubit, twoQubit), count, marked, iterations, index, auxiliaries);
        SetDepolarizingRate(0.0);
        // Noise can leave an auxiliary in |1⟩; it is reset, as a device would, before it is released.
        ResetAll(auxiliaries);
        MeasureIntegerReadingLossAsZero(index)
    }
}
