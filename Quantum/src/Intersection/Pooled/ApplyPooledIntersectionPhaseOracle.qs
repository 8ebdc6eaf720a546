namespace QuantumRayTracing.Intersection {
    /// # Summary
    /// One pooled query in phase form for Grover: a phase of −1 on every (ray, primitive) pair whose
    /// row is accepted in its ray's window, every work register back in |0⟩.
    ///
    /// # Input
    /// ## pool
    /// The pool's tables, from `PreparePooledIntersectionTables`.
    /// ## pair
    /// The pair register (primitive part low, ray part high).
    /// ## registers
    /// The work registers, in |0⟩.
    /// ## flag
    /// A qubit held in |1⟩: the flags' AND controls a Z on it, which kicks the phase back. It stays in |1⟩.
    internal operation ApplyPooledIntersectionPhaseOracle(pool : PooledIntersectionTables, pair : Qubit[], registers : PooledRegisters, flag : Qubit) : Unit is Adj + Ctl {
        within {
            ComputePooledIntersectionFlags(pool, pair, registers);
        } apply {
            Controlled Z(IntersectionFlags(registers.Row), flag);
        }
    }
}
