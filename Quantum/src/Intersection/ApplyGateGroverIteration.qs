namespace QuantumRayTracing.Intersection {
    import QuantumRayTracing.Search.ReflectAboutUniformSuperposition;

    /// # Summary
    /// One Grover iteration with the gate-level intersection oracle: the phase oracle, then the
    /// reflection about the uniform superposition over the primitives.
    ///
    /// # Input
    /// ## tables
    /// The ray's tables, from `PrepareIntersectionTables`.
    /// ## count
    /// Number of primitives N.
    /// ## index
    /// Index register, in the span of the uniform superposition over N and the marked states.
    /// ## registers
    /// The work registers, in |0⟩; they end in |0⟩.
    /// ## flag
    /// A qubit in |1⟩; it stays in |1⟩.
    internal operation ApplyGateGroverIteration(tables : IntersectionTables, count : Int, index : Qubit[], registers : IntersectionRegisters, flag : Qubit) : Unit is Adj + Ctl {
        ApplyIntersectionPhaseOracle(tables, index, registers, flag);
        ReflectAboutUniformSuperposition(count, Controlled Z(_, flag), index);
    }
}
