namespace QuantumRayTracing.Supersampling {
    /// # Summary
    /// Many QSS runs in one call: each request `(amplitudes, counterBits, shots)` gets `shots`
    /// independent readouts of `MeasureQssReadout`.
    ///
    /// # Output
    /// The readouts of each request, in order.
    operation MeasureQssBatch(requests : (Double[], Int, Int)[]) : Int[][] {
        mutable readouts = [];
        for (amplitudes, counterBits, shots) in requests {
            mutable own = [];
            for _ in 1..shots {
                set own += [MeasureQssReadout(amplitudes, counterBits)];
            }
            set readouts += [own];
        }
        readouts
    }
}
