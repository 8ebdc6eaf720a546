namespace QuantumRayTracing.Search {
    /// # Summary
    /// Reflects the index register about the uniform superposition over `count` indices, A S₀ A†:
    /// the diffusion half of a Grover iteration, the same for every oracle.
    ///
    /// # Input
    /// ## count
    /// Number of indices searched.
    /// ## index
    /// Index register of the search.
    /// ## flag
    /// A qubit in |1⟩; it stays in |1⟩. S₀ is a Z on it controlled by the flipped index register,
    /// so no |−⟩ ancilla is needed.
    operation ReflectAboutUniformSuperposition(count : Int, index : Qubit[], flag : Qubit) : Unit is Adj + Ctl {
        within {
            Adjoint PrepareUniformSuperposition(count, index);
            ApplyToEachCA(X, index);
        } apply {
            Controlled Z(index, flag);
        }
    }
}
