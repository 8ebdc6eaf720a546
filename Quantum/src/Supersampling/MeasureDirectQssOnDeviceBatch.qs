namespace QuantumRayTracing.Supersampling {
    /// # Summary
    /// Many `MeasureDirectQssOnDevice` runs at one pair of rates in one call: each request
    /// `(headAmplitude, counterBits, shots)` gets `shots` independent readouts.
    ///
    /// # Output
    /// The readouts of each request, in order, before any readout error.
    operation MeasureDirectQssOnDeviceBatch(oneQubit : Double, twoQubit : Double, requests : (Double, Int, Int)[]) : Int[][] {
        mutable readouts = [];
        for (headAmplitude, counterBits, shots) in requests {
            mutable own = [];
            for _ in 1..shots {
                set own += [MeasureDirectQssOnDevice(oneQubit, twoQubit, headAmplitude, counterBits)];
            }
            set readouts += [own];
        }
        readouts
    }
}
