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
        ApplyGateGroverSearchWith(PrepareIntersectionTables(input), Length(input.Bounds), iterations, index);
    }

    /// # Summary
    /// `ApplyGateGroverSearch` with every table lookup uncomputed by Toffoli gates instead of by
    /// measurement and feedback, and the loaded registers cleared by a second lookup whatever the
    /// construction: the same state on `index`, and for the narrow construction the same gates once
    /// `qrt export` has made the library's measured AND uncomputations unitary. It is what `qrt export`
    /// compiles: the QDK's QIR compile takes time quadratic in the number of feedback branches, and
    /// the lookups hold most of them; and the measured unlookup (`Adjoint Select`), which computes its
    /// phase fix-up classically from the measurement results, stops the QDK's QIR compile with an
    /// internal error.
    ///
    /// # Input
    /// ## input
    /// The ray's bounds, table and window constants.
    /// ## iterations
    /// Number of Grover iterations r ≥ 0.
    /// ## index
    /// Index register of ceil(log2 N) qubits, in |0⟩.
    operation ApplyGateGroverSearchWithUnitaryLookups(input : IntersectionInput, iterations : Int, index : Qubit[]) : Unit {
        let tables = PrepareIntersectionTables(input);
        // The tables of a measured unload are those of the lookup unload (narrow is compact unloading by lookup).
        ApplyGateGroverSearchWith(new IntersectionTables { ...tables, UnitaryLookups = true, MeasuredUnload = false }, Length(input.Bounds), iterations, index);
    }

    /// # Summary
    /// The search of `ApplyGateGroverSearch` on prepared tables.
    ///
    /// # Input
    /// ## tables
    /// The ray's tables, from `PrepareIntersectionTables`.
    /// ## count
    /// Number of primitives N.
    /// ## iterations
    /// Number of Grover iterations r ≥ 0.
    /// ## index
    /// Index register of `tables.IndexBits` qubits, in |0⟩.
    internal operation ApplyGateGroverSearchWith(tables : IntersectionTables, count : Int, iterations : Int, index : Qubit[]) : Unit {
        if iterations < 0 {
            fail $"iterations must be non-negative, got {iterations}";
        }
        if Length(index) != tables.IndexBits {
            fail $"the index register has {Length(index)} qubits; {count} primitives need {tables.IndexBits}";
        }
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
