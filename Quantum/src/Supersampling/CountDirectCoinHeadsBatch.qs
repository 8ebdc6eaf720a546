namespace QuantumRayTracing.Supersampling {
    import Std.Arrays.ForEach;

    /// # Summary
    /// Many `CountDirectCoinHeads` requests in one call, so the host pays the simulator's start-up
    /// cost once per batch.
    ///
    /// # Input
    /// ## requests
    /// `(headAmplitude, iterations, flips)` per request.
    ///
    /// # Output
    /// The head count of each request, in order.
    operation CountDirectCoinHeadsBatch(requests : (Double, Int, Int)[]) : Int[] {
        ForEach(CountDirectCoinHeads, requests)
    }
}
