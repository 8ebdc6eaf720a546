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
    /// (1 + BoundRegisters) · CoordinateBits + Axes + ValidQubits + DepthBits + 2.
    internal function IntersectionWorkQubits(tables : IntersectionTables) : Int {
        (1 + tables.BoundRegisters) * tables.CoordinateBits + tables.Axes + ValidQubits(tables) + tables.DepthBits + 2
    }

    /// # Summary
    /// The valid qubit: one, or none with constant bounds (validity is then applied under index control).
    internal function ValidQubits(tables : IntersectionTables) : Int {
        tables.BoundRegisters == 0 ? 0 | 1
    }
}
