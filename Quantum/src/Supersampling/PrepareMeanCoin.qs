namespace QuantumRayTracing.Supersampling {
    import QuantumRayTracing.Search.PrepareUniformSuperposition;
    import Std.Arrays.Most;
    import Std.Arrays.Tail;

    /// # Summary
    /// The coin whose head (coin qubit |1⟩, any subpixel) has probability (1/N) Σ a_i²: with
    /// a_i = √F(i) it is the Monte Carlo coin Q_{√F,0} of QCoin's first step and the state
    /// QSS amplifies (paper 003, eq. 20-24).
    ///
    /// # Input
    /// ## amplitudes
    /// One amplitude per subpixel, N = Length(amplitudes) ≥ 1.
    /// ## register
    /// The subpixel register followed by the coin qubit, all in |0⟩.
    internal operation PrepareMeanCoin(amplitudes : Double[], register : Qubit[]) : Unit is Adj + Ctl {
        let index = Most(register);
        PrepareUniformSuperposition(Length(amplitudes), index);
        ApplyCoinOracle(amplitudes, index, Tail(register));
    }
}
