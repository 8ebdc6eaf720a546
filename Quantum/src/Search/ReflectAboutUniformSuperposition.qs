namespace QuantumRayTracing.Search {
    /// # Summary
    /// Reflects the index register about the uniform superposition over `count` indices, A S₀ A†:
    /// the diffusion half of a Grover iteration, the same for every oracle.
    ///
    /// # Input
    /// ## count
    /// Number of indices searched.
    /// ## phaseOnAllOnes
    /// Applies a phase of −1 to the all-ones state of the qubits it is given: S₀ is this phase
    /// on the flipped index register, so no |−⟩ ancilla is needed. The lookup search passes
    /// `ApplyPhaseToAllOnes` with its auxiliaries; the gate-level search a Z on its flag qubit
    /// (held in |1⟩) controlled by the register.
    /// ## index
    /// Index register of the search.
    internal operation ReflectAboutUniformSuperposition(count : Int, phaseOnAllOnes : Qubit[] => Unit is Adj + Ctl, index : Qubit[]) : Unit is Adj + Ctl {
        ReflectAboutPreparedState(PrepareUniformSuperposition(count, _), X, phaseOnAllOnes, index);
    }

    /// # Summary
    /// Reflects `index` about the state `prepare` makes from |0…0⟩, A S₀ A†, with the X gates `x` around the phase:
    /// `ReflectAboutUniformSuperposition` in the gates of its caller (see `LookupGates`).
    internal operation ReflectAboutPreparedState(prepare : Qubit[] => Unit is Adj + Ctl, x : Qubit => Unit is Adj + Ctl, phaseOnAllOnes : Qubit[] => Unit is Adj + Ctl, index : Qubit[]) : Unit is Adj + Ctl {
        within {
            Adjoint prepare(index);
            ApplyToEachCA(x, index);
        } apply {
            phaseOnAllOnes(index);
        }
    }
}
