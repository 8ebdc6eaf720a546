namespace QuantumRayTracing.Intersection {
    /// # Summary
    /// The intersection oracle in phase form for Grover: a phase of −1 on every primitive p with
    /// i_r(p) = 1, every work register back in |0⟩.
    ///
    /// # Input
    /// ## tables
    /// The ray's tables, from `PrepareIntersectionTables`.
    /// ## index
    /// Index register, holding indices below the primitive count.
    /// ## registers
    /// The work registers, in |0⟩.
    /// ## flag
    /// A qubit held in |1⟩: the flags' AND controls a Z on it, which
    /// kicks the phase back. It stays in |1⟩.
    internal operation ApplyIntersectionPhaseOracle(tables : IntersectionTables, index : Qubit[], registers : IntersectionRegisters, flag : Qubit) : Unit is Adj + Ctl {
        within {
            ComputeIntersectionFlags(tables, index, registers);
        } apply {
            Controlled Z(IntersectionFlags(registers), flag);
        }
    }
}
