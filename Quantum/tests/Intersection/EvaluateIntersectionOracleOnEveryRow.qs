namespace QuantumRayTracing.Intersection {
    /// # Summary
    /// `EvaluateIntersectionOracle` on every basis state p < N of every input, in one call.
    ///
    /// # Input
    /// ## inputs
    /// One ray's search each.
    ///
    /// # Output
    /// Per input, per row p, the output and register values `EvaluateIntersectionOracle` returns.
    operation EvaluateIntersectionOracleOnEveryRow(inputs : IntersectionInput[]) : (Bool, Int[])[][] {
        mutable results = [];
        for input in inputs {
            mutable rows = [];
            for p in 0..Length(input.Bounds) - 1 {
                set rows += [EvaluateIntersectionOracle(input, p)];
            }
            set results += [rows];
        }
        results
    }
}
