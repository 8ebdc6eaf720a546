namespace QuantumRayTracing.Supersampling {
    import Std.Arrays.ForEach;

    /// # Summary
    /// Many `CountAncillaZeros` requests in one call, so the host pays the simulator's start-up
    /// cost once per batch.
    ///
    /// # Input
    /// ## requests
    /// `(amplitudes, power, shots)` per request.
    ///
    /// # Output
    /// The count of ancilla zeros of each request, in order.
    operation CountAncillaZerosBatch(requests : (Double[], Int, Int)[]) : Int[] {
        ForEach(CountAncillaZeros, requests)
    }
}
