namespace QuantumRayTracing.Intersection {
    /// # Summary
    /// The six qubits whose AND is i_r(p) once `ComputeIntersectionFlags` has run.
    ///
    /// # Input
    /// ## registers
    /// The oracle's work registers.
    ///
    /// # Output
    /// [valid, i_X, i_Y, i_Z, near, limit].
    function IntersectionFlags(registers : IntersectionRegisters) : Qubit[] {
        [registers.Valid] + registers.AxisFlags + registers.DepthFlags
    }
}
