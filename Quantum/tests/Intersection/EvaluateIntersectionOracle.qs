namespace QuantumRayTracing.Intersection {
    import Std.Arrays.ForEach;
    import Std.Measurement.MeasureInteger;

    /// # Summary
    /// Runs the XOR form of the oracle on the basis state |p⟩ with fresh registers and measures
    /// everything: the test of the oracle against the classical verify-rpc.
    ///
    /// # Input
    /// ## input
    /// The ray's bounds, table and window constants.
    /// ## p
    /// The basis index, below the primitive count.
    ///
    /// # Output
    /// The measured output i_r(p), and the measured values of the registers [index, rpc, coord,
    /// axis flags, valid, depth, near limit]: p if the oracle left the index alone, then all 0 if
    /// it uncomputed every work register.
    internal operation EvaluateIntersectionOracle(input : IntersectionInput, p : Int) : (Bool, Int[]) {
        let tables = PrepareIntersectionTables(input);
        if p < 0 or p >= Length(input.Bounds) {
            fail $"basis index {p} is outside 0..{Length(input.Bounds) - 1}";
        }
        use index = Qubit[tables.IndexBits];
        use work = Qubit[IntersectionWorkQubits(tables)];
        use output = Qubit();
        let registers = IntersectionRegistersOf(tables, work);
        ApplyXorInPlace(p, index);
        ApplyIntersectionOracle(tables, index, registers, output);
        let hit = MResetZ(output) == One;
        let all = [index, registers.Rpc, registers.Coord, registers.AxisFlags, registers.Valid, registers.Depth, registers.DepthFlags];
        (hit, ForEach(MeasureInteger, all))
    }
}
