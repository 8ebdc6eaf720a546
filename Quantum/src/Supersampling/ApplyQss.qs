namespace QuantumRayTracing.Supersampling {
    import Std.Canon.ApplyQFT;
    import Std.Canon.SwapReverseRegister;

    /// # Summary
    /// Quantum supersampling up to its measurement (paper 003 sec. 3.3, thesis 004 sec. 1.5.1): the
    /// counter register in uniform superposition, the mean coin prepared, counter qubit j controlling
    /// 2^j Grover operators, and the inverse QFT on the counter. `MeasureQssReadout` measures the
    /// counter; `qrt export qss` writes this as a circuit.
    ///
    /// # Input
    /// ## amplitudes
    /// √F(i) per subpixel, in [0, 1]; N = Length(amplitudes) ≥ 1.
    /// ## counterBits
    /// t ≥ 1 counter qubits: 2^t − 1 Grover operators, 2^(t+1) − 1 queries with the preparation.
    /// ## register
    /// The t counter qubits (qubit 0 the readout's least significant bit), then ceil(log2 N) subpixel
    /// qubits and the coin qubit, all in |0⟩. The coin register stays entangled with the counter.
    operation ApplyQss(amplitudes : Double[], counterBits : Int, register : Qubit[]) : Unit {
        if counterBits < 1 {
            fail $"counterBits must be at least 1, got {counterBits}";
        }
        let coinQubits = SubpixelQubits(Length(amplitudes)) + 1;
        if Length(register) != counterBits + coinQubits {
            fail $"{counterBits} counter bits and {Length(amplitudes)} subpixels need {counterBits + coinQubits} qubits, got {Length(register)}";
        }
        let counter = register[...counterBits - 1];
        let coin = register[counterBits...];
        let prepare = PrepareMeanCoin(amplitudes, _);
        ApplyToEach(H, counter);
        prepare(coin);
        for j in 0..counterBits - 1 {
            for _ in 1..1 <<< j {
                Controlled ApplyCoinGroverOperator([counter[j]], (prepare, MarkMeanCoinHead, coin));
            }
        }
        // ApplyQFT leaves the qubits in reversed order; the inverse of the whole transform reverses first.
        SwapReverseRegister(counter);
        Adjoint ApplyQFT(counter);
    }
}
