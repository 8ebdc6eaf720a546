namespace QuantumRayTracing.Intersection {
    /// # Summary
    /// The intersection operator Int_r of paper fig. 3: XORs i_r(p) into `output` for every
    /// primitive p in the index register, and returns every work register to |0⟩.
    ///
    /// # Input
    /// ## tables
    /// The ray's tables, from `PrepareIntersectionTables`.
    /// ## index
    /// Index register, holding indices below the primitive count.
    /// ## registers
    /// The work registers, in |0⟩; passed in so a caller can check they end in |0⟩.
    /// ## output
    /// The qubit i_r(p) is XORed into.
    internal operation ApplyIntersectionOracle(tables : IntersectionTables, index : Qubit[], registers : IntersectionRegisters, output : Qubit) : Unit is Adj + Ctl {
        within {
            ComputeIntersectionFlags(tables, index, registers);
        } apply {
            Controlled X(IntersectionFlags(registers), output);
        }
    }
}
