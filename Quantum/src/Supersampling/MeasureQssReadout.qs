namespace QuantumRayTracing.Supersampling {
    import QuantumRayTracing.Search.MeasureIntegerReadingLossAsZero;

    /// # Summary
    /// Quantum supersampling (paper 003 sec. 3.3, thesis 004 sec. 1.5.1): `ApplyQss` (the counter in
    /// uniform superposition, the mean coin prepared, counter qubit j controlling 2^j Grover
    /// operators, the inverse QFT on the counter), then the counter measured.
    ///
    /// # Input
    /// ## amplitudes
    /// √F(i) per subpixel (0 or 1 for a binary shader); N = Length(amplitudes) ≥ 1.
    /// ## counterBits
    /// t ≥ 1 counter qubits: 2^t − 1 Grover operators, 2^(t+1) − 1 queries with the preparation.
    ///
    /// # Output
    /// The counter readout y in 0..2^t − 1. With sin²θ the mean of F, y/2^t concentrates at
    /// θ/π and 1 − θ/π, so sin²(πy/2^t) estimates the mean.
    ///
    /// # Remarks
    /// Registers: t counter qubits, ceil(log2 N) subpixel qubits, one coin qubit.
    operation MeasureQssReadout(amplitudes : Double[], counterBits : Int) : Int {
        use counter = Qubit[counterBits];
        use register = Qubit[SubpixelQubits(Length(amplitudes)) + 1];
        ApplyQss(amplitudes, counterBits, counter + register);
        let readout = MeasureIntegerReadingLossAsZero(counter);
        ResetAll(register);
        readout
    }
}
