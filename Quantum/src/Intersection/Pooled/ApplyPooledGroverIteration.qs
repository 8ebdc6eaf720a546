namespace QuantumRayTracing.Intersection {
    import QuantumRayTracing.Search.ReflectAboutPreparedState;

    /// # Summary
    /// One Grover iteration of a pooled search: the pooled query in phase form, then the reflection
    /// about the uniform superposition over the pool's (ray, primitive) pairs.
    ///
    /// # Input
    /// ## pool
    /// The pool's tables, from `PreparePooledIntersectionTables`.
    /// ## pair
    /// The pair register, in the span of the uniform superposition over the pairs and the marked pairs.
    /// ## registers
    /// The work registers, in |0⟩; they end in |0⟩.
    /// ## flag
    /// A qubit in |1⟩; it stays in |1⟩.
    internal operation ApplyPooledGroverIteration(pool : PooledIntersectionTables, pair : Qubit[], registers : PooledRegisters, flag : Qubit) : Unit is Adj + Ctl {
        ApplyPooledIntersectionPhaseOracle(pool, pair, registers, flag);
        ReflectAboutPreparedState(PreparePoolPairs(pool.Primitives, pool.Rays, pool.PrimitiveBits, _), X, Controlled Z(_, flag), pair);
    }
}
