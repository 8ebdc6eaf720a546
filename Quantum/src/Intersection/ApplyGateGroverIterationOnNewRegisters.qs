namespace QuantumRayTracing.Intersection {
    /// # Summary
    /// Allocates the registers one gate-level search needs and applies one Grover iteration to
    /// them: the entry point for resource estimates of the oracle and the iteration.
    ///
    /// # Input
    /// ## input
    /// The ray's bounds, table and window constants.
    operation ApplyGateGroverIterationOnNewRegisters(input : IntersectionInput) : Unit {
        let tables = PrepareIntersectionTables(input);
        use index = Qubit[tables.IndexBits];
        use work = Qubit[IntersectionWorkQubits(tables)];
        use flag = Qubit();
        ApplyGateGroverIteration(tables, Length(input.Bounds), index, IntersectionRegistersOf(tables, work), flag);
        ResetAll(index + work + [flag]);
    }
}
