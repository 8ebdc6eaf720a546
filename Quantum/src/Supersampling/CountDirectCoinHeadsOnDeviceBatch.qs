namespace QuantumRayTracing.Supersampling {
    /// # Summary
    /// Many `CountDirectCoinHeadsOnDevice` requests at one one-qubit rate in one call.
    ///
    /// # Input
    /// ## oneQubit
    /// Depolarizing probability after each one-qubit gate.
    /// ## requests
    /// `(headAmplitude, iterations, flips)` per request.
    ///
    /// # Output
    /// The head count of each request, in order, before any readout error.
    operation CountDirectCoinHeadsOnDeviceBatch(oneQubit : Double, requests : (Double, Int, Int)[]) : Int[] {
        mutable heads = [];
        for (headAmplitude, iterations, flips) in requests {
            set heads += [CountDirectCoinHeadsOnDevice(oneQubit, headAmplitude, iterations, flips)];
        }
        heads
    }
}
