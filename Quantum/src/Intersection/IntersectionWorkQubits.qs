namespace QuantumRayTracing.Intersection {
    /// # Summary
    /// How many qubits the oracle's work registers take: rpc, coord, depth and six flags.
    ///
    /// # Input
    /// ## tables
    /// The ray's tables.
    ///
    /// # Output
    /// 2 · CoordinateBits + DepthBits + 6.
    function IntersectionWorkQubits(tables : IntersectionTables) : Int {
        2 * tables.CoordinateBits + tables.DepthBits + 6
    }
}
