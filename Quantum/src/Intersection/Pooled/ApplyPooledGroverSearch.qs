namespace QuantumRayTracing.Intersection {
    /// # Summary
    /// A pooled search up to its measurement, with every table lookup uncomputed by Toffoli gates and
    /// the loaded registers cleared by a second lookup (as `ApplyGateGroverSearchWithUnitaryLookups` does
    /// for one ray): prepares the uniform superposition over the pool's (ray, primitive) pairs in `pair`
    /// and applies `iterations` pooled Grover iterations. Every work qubit is back in |0⟩ and released;
    /// `pair` holds the state a measurement would read. `qrt export pooled-search` writes it as a circuit.
    ///
    /// # Input
    /// ## inputs
    /// The pool: one ray's search each, over the same primitives.
    /// ## iterations
    /// Number of Grover iterations r ≥ 0.
    /// ## pair
    /// The pair register, ceil(log2 N) primitive qubits then ceil(log2 rays) ray qubits, in |0⟩.
    operation ApplyPooledGroverSearchWithUnitaryLookups(inputs : IntersectionInput[], iterations : Int, pair : Qubit[]) : Unit {
        let prepared = PreparePooledIntersectionTables(inputs);
        let pool = new PooledIntersectionTables { ...prepared, Rows = new IntersectionTables { ...prepared.Rows, UnitaryLookups = true, MeasuredUnload = false } };
        if iterations < 0 {
            fail $"iterations must be non-negative, got {iterations}";
        }
        if Length(pair) != pool.PrimitiveBits + pool.RayBits {
            fail $"the pair register has {Length(pair)} qubits; {pool.Rays} rays of {pool.Primitives} primitives need {pool.PrimitiveBits + pool.RayBits}";
        }
        use work = Qubit[PooledWorkQubits(pool)];
        use flag = Qubit();
        let registers = PooledRegistersOf(pool, work);
        within {
            X(flag);
        } apply {
            PreparePoolPairs(pool.Primitives, pool.Rays, pool.PrimitiveBits, pair);
            for _ in 1..iterations {
                ApplyPooledGroverIteration(pool, pair, registers, flag);
            }
        }
    }
}
