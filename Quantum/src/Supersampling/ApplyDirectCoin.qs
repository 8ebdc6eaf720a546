namespace QuantumRayTracing.Supersampling {
    import Std.Math.ArcSin;

    /// # Summary
    /// One flip of the QCoin paper's hardware coin (sec. 6) up to its measurement: prepares
    /// √(1 − f)|0⟩ + √f|1⟩ with one Ry and applies `iterations` Grover operators. `CountDirectCoinHeads`
    /// measures it; `qrt export coin --mean` writes it as a circuit.
    ///
    /// # Input
    /// ## headAmplitude
    /// √f in [0, 1].
    /// ## iterations
    /// Grover operators m ≥ 0; the head then has probability sin²((2m+1)θ), sin θ = √f.
    /// ## coin
    /// One qubit, in |0⟩.
    ///
    /// # Remarks
    /// The Grover operator −A S₀ A† S_χ is A Z A† Z here (S_χ = Z, and S₀ = −Z on one qubit), four
    /// gates with no global phase to repair: the coin is never run under control.
    operation ApplyDirectCoin(headAmplitude : Double, iterations : Int, coin : Qubit[]) : Unit {
        if Length(coin) != 1 {
            fail $"the direct coin is one qubit, got {Length(coin)}";
        }
        let angle = 2.0 * ArcSin(headAmplitude);
        let qubit = coin[0];
        Ry(angle, qubit);
        for _ in 1..iterations {
            Z(qubit);
            Ry(-angle, qubit);
            Z(qubit);
            Ry(angle, qubit);
        }
    }
}
