namespace QuantumRayTracing.Intersection {
    /// # Summary
    /// How many qubits the oracle's work registers take: rpc, coord (one or two bound registers),
    /// one flag per tested axis, valid, depth, near and limit.
    ///
    /// # Input
    /// ## tables
    /// The ray's tables.
    ///
    /// # Output
    /// (1 + BoundRegisters) · CoordinateBits + Axes + 1 + DepthBits + 2.
    internal function IntersectionWorkQubits(tables : IntersectionTables) : Int {
        (1 + tables.BoundRegisters) * tables.CoordinateBits + tables.Axes + 1 + tables.DepthBits + 2
    }
}
