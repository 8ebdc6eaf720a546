namespace QuantumRayTracing.Supersampling {
    /// # Summary
    /// One coin flip up to its measurement: prepares the coin and applies `iterations` Grover operators.
    ///
    /// # Input
    /// ## prepare
    /// The coin's preparation A (`PrepareMeanCoin` or `PrepareShiftedCoin` with its amplitudes).
    /// ## markHead
    /// S_χ, the phase on a head.
    /// ## iterations
    /// Grover operators m ≥ 0.
    /// ## register
    /// The subpixel qubits and the coin qubit (last), in |0⟩.
    internal operation ApplyCoinFlip(prepare : (Qubit[] => Unit is Adj + Ctl), markHead : (Qubit[] => Unit is Adj + Ctl), iterations : Int, register : Qubit[]) : Unit {
        prepare(register);
        for _ in 1..iterations {
            ApplyCoinGroverOperator(prepare, markHead, register);
        }
    }
}
