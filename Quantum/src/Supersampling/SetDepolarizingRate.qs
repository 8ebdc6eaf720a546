namespace QuantumRayTracing.Supersampling {
    import Std.Diagnostics.ConfigurePauliNoise;

    /// # Summary
    /// Sets the simulator's Pauli noise for the gates that follow: p/3 each of X, Y and Z after each
    /// gate on every qubit it touches. The device circuits call it before each gate with that gate's
    /// rate (one-qubit or two-qubit), and with 0 before measuring: their readout error is applied by
    /// the host to the measured bits.
    ///
    /// # Input
    /// ## rate
    /// p in [0, 1]; 0 turns the noise off.
    internal function SetDepolarizingRate(rate : Double) : Unit {
        ConfigurePauliNoise(rate / 3.0, rate / 3.0, rate / 3.0);
    }
}
