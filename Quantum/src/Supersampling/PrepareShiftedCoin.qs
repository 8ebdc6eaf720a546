namespace QuantumRayTracing.Supersampling {
    import QuantumRayTracing.Search.PrepareUniformSuperposition;
    import Std.Arrays.Most;
    import Std.Arrays.Tail;

    /// # Summary
    /// QCoin's coin (paper 003, eq. 30-33): uniform superposition over the subpixels, the oracle,
    /// and the superposition undone, so the head |1⟩ ⊗ |0…0⟩ has amplitude (1/N) Σ a_i. With
    /// a_i = F(i) − E that is f − E, the shifted mean.
    ///
    /// # Input
    /// ## amplitudes
    /// One amplitude per subpixel, N = Length(amplitudes) ≥ 1.
    /// ## register
    /// The subpixel register followed by the coin qubit, all in |0⟩.
    ///
    /// # Remarks
    /// The paper writes the outer steps as H on every index qubit; the exact uniform preparation
    /// (and its adjoint) is the same for a power-of-two N and stays exact for any other N.
    internal operation PrepareShiftedCoin(amplitudes : Double[], register : Qubit[]) : Unit is Adj + Ctl {
        let index = Most(register);
        within {
            PrepareUniformSuperposition(Length(amplitudes), index);
        } apply {
            ApplyCoinOracle(amplitudes, index, Tail(register));
        }
    }
}
