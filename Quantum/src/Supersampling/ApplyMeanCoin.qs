namespace QuantumRayTracing.Supersampling {
    /// # Summary
    /// One flip of the mean coin over the subpixel amplitudes up to its measurement: the uniform
    /// superposition over the subpixels, each one's amplitude rotated onto the coin qubit, then
    /// `iterations` Grover operators (what `CountCoinHeads` does per flip, unshifted).
    /// `qrt export coin --values` writes it as a circuit.
    ///
    /// # Input
    /// ## amplitudes
    /// One amplitude per subpixel (the square root of its value), in [0, 1].
    /// ## iterations
    /// Grover operators m ≥ 0; the coin then reads 1 with probability sin²((2m+1)θ), sin²θ the mean value.
    /// ## register
    /// ceil(log2 N) subpixel qubits and the coin qubit (last), in |0⟩.
    operation ApplyMeanCoin(amplitudes : Double[], iterations : Int, register : Qubit[]) : Unit {
        if Length(register) != SubpixelQubits(Length(amplitudes)) + 1 {
            fail $"{Length(amplitudes)} subpixels need {SubpixelQubits(Length(amplitudes)) + 1} qubits, got {Length(register)}";
        }
        ApplyCoinFlip(PrepareMeanCoin(amplitudes, _), MarkMeanCoinHead, iterations, register);
    }
}
