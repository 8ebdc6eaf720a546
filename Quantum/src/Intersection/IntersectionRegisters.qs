namespace QuantumRayTracing.Intersection {
    /// # Summary
    /// The oracle's work registers besides the index register (paper figs. 3-5), all in |0⟩
    /// between oracle calls.
    ///
    /// # Input
    /// ## Rpc
    /// The ray/plane point's coordinate on the axis being tested (CoordinateBits qubits).
    /// ## Coord
    /// The primitive's bounds on that axis: its minimum, then its maximum (CoordinateBits qubits),
    /// or both at once (minimum, then maximum: 2 · CoordinateBits qubits).
    /// ## AxisFlags
    /// One per tested axis (i_X, i_Y, i_Z, or the two axes in the primitive's plane): the point
    /// lies within the bounds on that axis.
    /// ## Valid
    /// The row holds a ray/plane point: one qubit, or none with constant bounds, where a row
    /// without a point has its first axis flag cleared instead.
    /// ## Depth
    /// The row's depth (DepthBits qubits).
    /// ## DepthFlags
    /// [near, limit]: depth ≥ Near, and (depth, p) below the limit.
    internal struct IntersectionRegisters {
        Rpc : Qubit[],
        Coord : Qubit[],
        AxisFlags : Qubit[],
        Valid : Qubit[],
        Depth : Qubit[],
        DepthFlags : Qubit[],
    }
}
