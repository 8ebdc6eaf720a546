namespace QuantumRayTracing.Intersection {
    /// # Summary
    /// One pooled query in XOR form: XORs into `output`, for every (ray, primitive) pair in the pair
    /// register, whether that ray's row for that primitive is accepted in its window, and returns
    /// every work register to |0⟩.
    ///
    /// # Input
    /// ## pool
    /// The pool's tables, from `PreparePooledIntersectionTables`.
    /// ## pair
    /// The pair register (primitive part low, ray part high).
    /// ## registers
    /// The work registers, in |0⟩; passed in so a caller can check they end in |0⟩.
    /// ## output
    /// The qubit the pair's test is XORed into.
    internal operation ApplyPooledIntersectionOracle(pool : PooledIntersectionTables, pair : Qubit[], registers : PooledRegisters, output : Qubit) : Unit is Adj + Ctl {
        within {
            ComputePooledIntersectionFlags(pool, pair, registers);
        } apply {
            Controlled X(IntersectionFlags(registers.Row), output);
        }
    }
}
