namespace QuantumRayTracing.Intersection {
    /// # Summary
    /// Allocates the registers of a pooled search and applies one of its Grover iterations: the entry
    /// point for resource estimates of the iteration.
    ///
    /// # Input
    /// ## inputs
    /// The pool: one ray's search each, over the same primitives.
    operation ApplyPooledGroverIterationOnNewRegisters(inputs : IntersectionInput[]) : Unit {
        let pool = PreparePooledIntersectionTables(inputs);
        use pair = Qubit[pool.PrimitiveBits + pool.RayBits];
        use work = Qubit[PooledWorkQubits(pool)];
        use flag = Qubit();
        ApplyPooledGroverIteration(pool, pair, PooledRegistersOf(pool, work), flag);
        ResetAll(pair + work + [flag]);
    }
}
