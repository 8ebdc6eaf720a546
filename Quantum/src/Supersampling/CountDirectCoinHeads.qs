namespace QuantumRayTracing.Supersampling {
    import QuantumRayTracing.Search.MeasureBitReadingLossAsZero;

    /// # Summary
    /// Flips the single-qubit coin √(1 − f)|0⟩ + √f|1⟩ `flips` times, each time preparing it
    /// afresh with one Ry and amplifying it `iterations` times, and counts the heads (|1⟩): the
    /// QCoin paper's hardware coin (sec. 6), whose oracle prepares the mean directly.
    ///
    /// # Input
    /// ## headAmplitude
    /// √f in [0, 1]: the head has probability f before amplification.
    /// ## iterations
    /// Grover operators per flip, m ≥ 0: a flip costs 1 + 2m queries, as every coin's does.
    /// ## flips
    /// Number of flips, ≥ 0.
    ///
    /// # Output
    /// The number of heads; after m operators each flip shows a head with probability
    /// sin²((2m+1)θ), sin θ = √f.
    ///
    /// # Remarks
    /// One qubit. The Grover operator −A S₀ A† S_χ is A Z A† Z here (S_χ = Z, and S₀ = −Z on one
    /// qubit), four gates with no global phase to repair: the coin is never run under control.
    internal operation CountDirectCoinHeads(headAmplitude : Double, iterations : Int, flips : Int) : Int {
        mutable heads = 0;
        use coin = Qubit();
        for _ in 1..flips {
            ApplyDirectCoin(headAmplitude, iterations, [coin]);
            if MeasureBitReadingLossAsZero(coin) {
                set heads += 1;
            }
        }
        heads
    }
}
