namespace QuantumRayTracing.Supersampling {
    import Std.Arrays.ForEach;

    /// # Summary
    /// Many `CountCoinHeads` requests in one call, so the host pays the simulator's start-up
    /// cost once per batch.
    ///
    /// # Input
    /// ## requests
    /// `(shifted, amplitudes, iterations, flips)` per request.
    ///
    /// # Output
    /// The head count of each request, in order.
    operation CountCoinHeadsBatch(requests : (Bool, Double[], Int, Int)[]) : Int[] {
        ForEach(CountCoinHeads, requests)
    }
}
