namespace QuantumRayTracing.Supersampling {
    import Std.Math.ArcSin;
    import Std.Math.AbsD;

    /// # Summary
    /// The shader oracle: rotates `coin` so that, for subpixel i, it reads
    /// √(1 − a_i²)|0⟩ + a_i|1⟩, where a_i = `amplitudes[i]`.
    ///
    /// # Input
    /// ## amplitudes
    /// One amplitude per subpixel, each in [−1, 1]. The host chooses them: √F(i) for the mean
    /// coin of QSS and Monte Carlo, F(i) − E for QCoin's shifted coin Q_{F,E} (paper 003, eq. 29).
    /// ## index
    /// Little-endian subpixel register, at least ceil(log2 Length(amplitudes)) qubits.
    /// ## coin
    /// The coin qubit, in |0⟩ on every subpixel before the call.
    ///
    /// # Remarks
    /// For binary subpixels (a_i ∈ {0, 1}) this is the phase-marking oracle of the thesis (004)
    /// written with a coin: a_i = 1 flips the coin, and a Z on the coin marks the subpixel.
    /// A zero amplitude costs no gate.
    internal operation ApplyCoinOracle(amplitudes : Double[], index : Qubit[], coin : Qubit) : Unit is Adj + Ctl {
        for i in 0..Length(amplitudes) - 1 {
            if AbsD(amplitudes[i]) > 0.0 {
                ApplyControlledOnInt(i, Ry(2.0 * ArcSin(amplitudes[i]), _), index, coin);
            }
        }
    }
}
