namespace QuantumRayTracing.Intersection {
    /// # Summary
    /// Allocates the registers the intersection operator Int_r needs and applies it once, with its
    /// output in a fresh qubit: the entry point for resource estimates of the oracle alone (paper
    /// fig. 3 and table 9).
    ///
    /// # Input
    /// ## input
    /// The ray's bounds, table, window constants and construction.
    operation ApplyIntersectionOracleOnNewRegisters(input : IntersectionInput) : Unit {
        let tables = PrepareIntersectionTables(input);
        use index = Qubit[tables.IndexBits];
        use work = Qubit[IntersectionWorkQubits(tables)];
        use output = Qubit();
        ApplyIntersectionOracle(tables, index, IntersectionRegistersOf(tables, work), output);
        ResetAll(index + work + [output]);
    }
}
