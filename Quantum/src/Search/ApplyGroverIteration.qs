namespace QuantumRayTracing.Search {
    /// # Summary
    /// Applies one Grover iteration Q = −A S₀ A† O: the marking oracle, then the reflection
    /// about the uniform superposition over `count` indices.
    ///
    /// # Input
    /// ## count
    /// Number of indices searched.
    /// ## marked
    /// Indices the oracle marks.
    /// ## index
    /// Index register holding a state prepared by `PrepareUniformSuperposition(count, _)`.
    /// ## flag
    /// Oracle output qubit in |1⟩; it stays in |1⟩.
    operation ApplyGroverIteration(count : Int, marked : Int[], index : Qubit[], flag : Qubit) : Unit is Adj + Ctl {
        ApplyMarkingOracle(marked, index, flag);
        ReflectAboutUniformSuperposition(count, index, flag);
    }
}
