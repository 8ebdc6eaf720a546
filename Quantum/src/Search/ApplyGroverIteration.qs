namespace QuantumRayTracing.Search {
    /// # Summary
    /// Applies one Grover iteration Q = −A S₀ A† O: the marking oracle, then the reflection
    /// about the uniform superposition over `count` indices.
    ///
    /// # Input
    /// ## gates
    /// The gates to write it in: `IdealLookupGates()`, or `DeviceLookupGates` under a device noise model.
    /// ## count
    /// Number of indices searched.
    /// ## marked
    /// Indices the oracle marks.
    /// ## index
    /// Index register holding a state prepared by `PrepareUniformSuperposition(count, _)`.
    /// ## auxiliaries
    /// `PhaseAuxiliaryCount(Length(index))` qubits in |0⟩; they end in |0⟩.
    internal operation ApplyGroverIteration(gates : LookupGates, count : Int, marked : Int[], index : Qubit[], auxiliaries : Qubit[]) : Unit is Adj + Ctl {
        ApplyMarkingOracle(gates, marked, index, auxiliaries);
        ReflectAboutPreparedState(gates.PrepareUniform(count, _), gates.X, ApplyPhaseToAllOnes(gates, _, auxiliaries), index);
    }
}
