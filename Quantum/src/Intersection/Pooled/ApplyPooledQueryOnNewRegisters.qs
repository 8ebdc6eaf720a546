namespace QuantumRayTracing.Intersection {
    /// # Summary
    /// Allocates the registers of a pooled search and applies one pooled query (the XOR form, into a
    /// fresh output qubit): the entry point for resource estimates of the query alone.
    ///
    /// # Input
    /// ## inputs
    /// The pool: one ray's search each, over the same primitives.
    operation ApplyPooledQueryOnNewRegisters(inputs : IntersectionInput[]) : Unit {
        let pool = PreparePooledIntersectionTables(inputs);
        use pair = Qubit[pool.PrimitiveBits + pool.RayBits];
        use work = Qubit[PooledWorkQubits(pool)];
        use output = Qubit();
        ApplyPooledIntersectionOracle(pool, pair, PooledRegistersOf(pool, work), output);
        ResetAll(pair + work + [output]);
    }
}
