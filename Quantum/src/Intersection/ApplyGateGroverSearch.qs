namespace QuantumRayTracing.Intersection {
    import QuantumRayTracing.Search.PrepareUniformSuperposition;

    /// # Summary
    /// One ray's gate-level Grover search up to its measurement: prepares the uniform superposition
    /// over the ray's primitives in `index` and applies `iterations` Grover iterations with the
    /// gate-level intersection oracle. Every work qubit is back in |0⟩ and released; `index` holds
    /// the state a measurement would read. `MeasureGateGroverSearch` measures it, `qrt export`
    /// writes it as a circuit.
    ///
    /// # Input
    /// ## input
    /// The ray's bounds, table and window constants.
    /// ## iterations
    /// Number of Grover iterations r ≥ 0.
    /// ## index
    /// Index register of ceil(log2 N) qubits, in |0⟩.
    operation ApplyGateGroverSearch(input : IntersectionInput, iterations : Int, index : Qubit[]) : Unit {
        if iterations < 0 {
            fail $"iterations must be non-negative, got {iterations}";
        }
        let tables = PrepareIntersectionTables(input);
        if Length(index) != tables.IndexBits {
            fail $"the index register has {Length(index)} qubits; {Length(input.Bounds)} primitives need {tables.IndexBits}";
        }
        let count = Length(input.Bounds);
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
    }
}
