namespace QuantumRayTracing.Intersection {
    /// # Summary
    /// The qubits whose AND is i_r(p) once `ComputeIntersectionFlags` has run: six, or five when only
    /// the two in-plane axes are tested, one fewer with constant bounds (no valid qubit).
    ///
    /// # Input
    /// ## registers
    /// The oracle's work registers.
    ///
    /// # Output
    /// [valid, the axis flags, near, limit].
    internal function IntersectionFlags(registers : IntersectionRegisters) : Qubit[] {
        registers.Valid + registers.AxisFlags + registers.DepthFlags
    }
}
