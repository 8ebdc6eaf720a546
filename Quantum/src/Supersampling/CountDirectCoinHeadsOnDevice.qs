namespace QuantumRayTracing.Supersampling {
    import Std.Math.ArcSin;
    import QuantumRayTracing.Search.MeasureBitReadingLossAsZero;

    /// # Summary
    /// `CountDirectCoinHeads` under a device noise model: every gate of the single-qubit coin (one Ry,
    /// then Z, Ry†, Z, Ry per Grover operator) is followed by depolarizing noise at the one-qubit rate;
    /// the measurement itself is left clean, as the host flips read bits by the readout error.
    ///
    /// # Input
    /// ## oneQubit
    /// Depolarizing probability after each one-qubit gate.
    /// ## headAmplitude
    /// √f in [0, 1].
    /// ## iterations
    /// Grover operators per flip, m ≥ 0.
    /// ## flips
    /// Number of flips, ≥ 0.
    ///
    /// # Output
    /// The number of heads read before any readout error.
    internal operation CountDirectCoinHeadsOnDevice(oneQubit : Double, headAmplitude : Double, iterations : Int, flips : Int) : Int {
        let angle = 2.0 * ArcSin(headAmplitude);
        mutable heads = 0;
        use coin = Qubit();
        for _ in 1..flips {
            SetDepolarizingRate(oneQubit);
            Ry(angle, coin);
            for _ in 1..iterations {
                Z(coin);
                Ry(-angle, coin);
                Z(coin);
                Ry(angle, coin);
            }
            SetDepolarizingRate(0.0);
            if MeasureBitReadingLossAsZero(coin) {
                set heads += 1;
            }
        }
        heads
    }
}
