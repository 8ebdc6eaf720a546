namespace QuantumRayTracing.Intersection {
    import Std.Arrays.ForEach;

    /// # Summary
    /// Runs many gate-level Grover searches in one call, so the host pays the simulator's start-up
    /// cost once per batch.
    ///
    /// # Input
    /// ## requests
    /// One `(input, iterations)` pair per search, as taken by `MeasureGateGroverSearch`.
    ///
    /// # Output
    /// The measured index of each request, in request order.
    operation MeasureGateGroverBatch(requests : (IntersectionInput, Int)[]) : Int[] {
        ForEach(MeasureGateGroverSearch, requests)
    }
}
