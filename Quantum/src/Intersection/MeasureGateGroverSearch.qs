namespace QuantumRayTracing.Intersection {
    import Std.Measurement.MeasureInteger;
    import Std.Math.BitSizeI;
    import Std.Math.MaxI;

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
        // MaxI leaves an empty input to the tables' own error message.
        use index = Qubit[BitSizeI(MaxI(Length(input.Bounds) - 1, 0))];
        ApplyGateGroverSearch(input, iterations, index);
        MeasureInteger(index)
    }
}
