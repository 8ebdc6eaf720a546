namespace QuantumRayTracing.Search {
    /// # Summary
    /// `MeasureGroverBatch` under a device noise model: each request runs `MeasureGroverSearchOnDevice` at the
    /// given rates, and its measured index comes back before any readout error.
    ///
    /// # Input
    /// ## oneQubit
    /// Depolarizing probability after each one-qubit gate.
    /// ## twoQubit
    /// Depolarizing probability on each qubit after each gate on two or more qubits.
    /// ## requests
    /// One `(count, marked, iterations)` tuple per search; every count a power of two.
    ///
    /// # Output
    /// The measured index of each request, in request order.
    operation MeasureGroverBatchOnDevice(oneQubit : Double, twoQubit : Double, requests : (Int, Int[], Int)[]) : Int[] {
        mutable measured = [];
        for (count, marked, iterations) in requests {
            set measured += [MeasureGroverSearchOnDevice(oneQubit, twoQubit, count, marked, iterations)];
        }
        measured
    }
}
