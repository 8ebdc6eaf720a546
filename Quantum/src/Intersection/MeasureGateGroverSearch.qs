namespace QuantumRayTracing.Intersection {
    import Std.Measurement.MeasureInteger;
    import QuantumRayTracing.Search.PrepareUniformSuperposition;

    /// # Summary
    /// Prepares the uniform superposition over the ray's primitives, applies `iterations` Grover
    /// iterations with the gate-level intersection oracle, and measures the index register.
    ///
    /// # Input
    /// ## input
    /// The ray's bounds, table and window constants.
    /// ## iterations
    /// Number of Grover iterations r ≥ 0; r = 0 samples the uniform superposition.
    ///
    /// # Output
    /// The measured index, always below the primitive count.
    ///
    /// # Remarks
    /// Unlike `MeasureGroverSearch` this does not mark the complement when most rows are marked:
    /// the oracle is the circuit, not a list.
    operation MeasureGateGroverSearch(input : IntersectionInput, iterations : Int) : Int {
        if iterations < 0 {
            fail $"iterations must be non-negative, got {iterations}";
        }
        let tables = PrepareIntersectionTables(input);
        let count = Length(input.Bounds);
        use index = Qubit[tables.IndexBits];
        use work = Qubit[IntersectionWorkQubits(tables)];
        use flag = Qubit();
        let registers = IntersectionRegistersOf(tables, work);
        within {
            X(flag);
        } apply {
            PrepareUniformSuperposition(count, index);
            for _ in 1..iterations {
                ApplyGateGroverIteration(tables, count, index, registers, flag);
            }
        }
        MeasureInteger(index)
    }
}
