namespace QuantumRayTracing.Capacity {
    import Std.Measurement.MeasureInteger;

    /// # Summary
    /// Prepares an entangled state with all 2^n amplitudes nonzero on `qubits` qubits and measures
    /// it: the widest state a circuit of that width can make, for measuring how much memory the
    /// simulator spends per amplitude.
    ///
    /// # Input
    /// ## qubits
    /// Width n ≥ 1 of the state.
    ///
    /// # Output
    /// The measured basis state.
    ///
    /// # Remarks
    /// H on every qubit alone would leave a product state; the CNOT-T-H ladder entangles each
    /// qubit with the next, so no simulator can store it as smaller factors.
    operation MeasureDenseState(qubits : Int) : Int {
        if qubits < 1 {
            fail $"qubits must be at least 1, got {qubits}";
        }
        use register = Qubit[qubits];
        ApplyToEach(H, register);
        for k in 0..qubits - 2 {
            CNOT(register[k], register[k + 1]);
            T(register[k + 1]);
            H(register[k]);
        }
        let outcome = MeasureInteger(register);
        ResetAll(register);
        outcome
    }
}
