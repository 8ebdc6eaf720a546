namespace QuantumRayTracing.Search {
    import Std.Math.BitSizeI;

    /// # Summary
    /// Allocates the registers one search over `count` indices needs and applies one Grover
    /// iteration to them: the entry point for resource estimates of the iteration alone.
    ///
    /// # Input
    /// ## count
    /// Number of indices searched.
    /// ## marked
    /// Indices the oracle marks.
    operation ApplyGroverIterationOnNewRegisters(count : Int, marked : Int[]) : Unit {
        use index = Qubit[BitSizeI(count - 1)];
        use auxiliaries = Qubit[PhaseAuxiliaryCount(Length(index))];
        ApplyGroverIteration(IdealLookupGates(), count, marked, index, auxiliaries);
        ResetAll(index);
    }
}
