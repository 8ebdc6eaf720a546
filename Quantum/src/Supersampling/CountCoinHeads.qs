namespace QuantumRayTracing.Supersampling {
    import Std.Arrays.Most;
    import Std.Arrays.Tail;
    import QuantumRayTracing.Search.MeasureBitReadingLossAsZero;
    import QuantumRayTracing.Search.MeasureIntegerReadingLossAsZero;

    /// # Summary
    /// Flips a coin `flips` times, each time preparing it afresh and amplifying it `iterations`
    /// times, and counts the heads.
    ///
    /// # Input
    /// ## shifted
    /// false: the mean coin (head = coin |1⟩, probability (1/N) Σ a_i²); true: QCoin's shifted
    /// coin (head = coin |1⟩ with subpixel register 0, amplitude (1/N) Σ a_i).
    /// ## amplitudes
    /// One amplitude per subpixel, in [−1, 1]; N = Length(amplitudes) ≥ 1.
    /// ## iterations
    /// Grover operators per flip, m ≥ 0: a flip costs 1 + 2m queries.
    /// ## flips
    /// Number of flips, ≥ 0.
    ///
    /// # Output
    /// The number of heads.
    ///
    /// # Remarks
    /// Registers: ceil(log2 N) subpixel qubits and one coin qubit.
    operation CountCoinHeads(shifted : Bool, amplitudes : Double[], iterations : Int, flips : Int) : Int {
        let width = SubpixelQubits(Length(amplitudes));
        let prepare = shifted ? PrepareShiftedCoin(amplitudes, _) | PrepareMeanCoin(amplitudes, _);
        let markHead = shifted ? MarkShiftedCoinHead | MarkMeanCoinHead;
        mutable heads = 0;
        use register = Qubit[width + 1];
        for _ in 1..flips {
            ApplyCoinFlip(prepare, markHead, iterations, register);
            let coin = MeasureBitReadingLossAsZero(Tail(register));
            let index = MeasureIntegerReadingLossAsZero(Most(register));
            if coin and (not shifted or index == 0) {
                set heads += 1;
            }
            ResetAll(register);
        }
        heads
    }
}
