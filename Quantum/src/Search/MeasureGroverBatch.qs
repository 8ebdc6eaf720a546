namespace QuantumRayTracing.Search {
    import Std.Arrays.ForEach;

    /// # Summary
    /// Runs many independent Grover searches in one call and returns their measured indices,
    /// so that the host pays the simulator's start-up cost once per batch, not once per search.
    ///
    /// # Input
    /// ## requests
    /// One `(count, marked, iterations)` tuple per search, as taken by `MeasureGroverSearch`.
    ///
    /// # Output
    /// The measured index of each request, in request order.
    operation MeasureGroverBatch(requests : (Int, Int[], Int)[]) : Int[] {
        ForEach(MeasureGroverSearch, requests)
    }
}
