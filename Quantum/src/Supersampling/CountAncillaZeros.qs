namespace QuantumRayTracing.Supersampling {
    import QuantumRayTracing.Search.MeasureBitReadingLossAsZero;

    /// # Summary
    /// The single-ancilla phase-estimation shot of QSS with Bayesian phase estimation, `shots`
    /// times: ancilla |+⟩, the mean coin prepared, the ancilla controlling `power` Grover
    /// operators, the ancilla read in the X basis; counts the shots that read 0.
    ///
    /// # Input
    /// ## amplitudes
    /// One amplitude per subpixel, as for `CountCoinHeads`'s mean coin (√F(i) for the mean f).
    /// ## power
    /// k ≥ 0 controlled Grover operators: a shot costs 1 + 2k queries.
    /// ## shots
    /// Number of shots, ≥ 0.
    ///
    /// # Output
    /// The shots whose ancilla read 0.
    ///
    /// # Remarks
    /// The coin is an equal-weight superposition of the Grover operator's eigenvectors, eigenphases
    /// ±2θ with sin²θ = f, so the ancilla reads 0 with probability ½ + ½·cos(2kθ) = cos²(kθ).
    /// Registers: one ancilla, ceil(log2 N) subpixel qubits and one coin qubit.
    internal operation CountAncillaZeros(amplitudes : Double[], power : Int, shots : Int) : Int {
        let prepare = PrepareMeanCoin(amplitudes, _);
        mutable zeros = 0;
        use ancilla = Qubit();
        use register = Qubit[SubpixelQubits(Length(amplitudes)) + 1];
        for _ in 1..shots {
            H(ancilla);
            prepare(register);
            for _ in 1..power {
                Controlled ApplyCoinGroverOperator([ancilla], (prepare, MarkMeanCoinHead, register));
            }
            H(ancilla);
            if not MeasureBitReadingLossAsZero(ancilla) {
                set zeros += 1;
            }
            Reset(ancilla);
            ResetAll(register);
        }
        zeros
    }
}
