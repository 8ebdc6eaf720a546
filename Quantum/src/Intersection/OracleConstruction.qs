namespace QuantumRayTracing.Intersection {
    /// # Summary
    /// How the gate-level oracle is built: the choices that trade lookups, comparators and qubits
    /// against each other without changing what it computes.
    ///
    /// # Input
    /// ## InPlaneAxes
    /// Test only the two axes in each primitive's plane. On its flat axis the ray/plane point is the
    /// plane itself and min = max = plane, so that test always passes; skipping it saves one axis
    /// step (two lookups and two comparators) and one flag qubit. False tests x, y and z for every
    /// primitive, as the paper's fig. 4 does.
    /// ## BothBounds
    /// Load an axis's minimum and maximum into two registers at once, so each axis step needs one
    /// lookup fewer (no min-to-max step), at the cost of one more coordinate register.
    /// ## MeasuredUnload
    /// Clear the loaded registers with the standard library's measurement-based unlookup
    /// (`Adjoint Select`: X-basis measurements, then a phase lookup over the index), which needs
    /// far fewer Toffolis than a lookup but 2^⌊n/2⌋ + 2^⌈n/2⌉ − n − 2 auxiliary qubits for its power
    /// products. False clears them with a second lookup of the same data (no auxiliaries beyond the
    /// lookup's n − 1).
    /// ## ConstantBounds
    /// Load no bound at all: compare the point with each primitive's minimum and maximum as classical
    /// constants, each comparison controlled on the index register holding that primitive. No
    /// coordinate register beyond the point's, at the price of 2N controlled comparators per axis
    /// instead of one lookup; overrides `BothBounds`.
    struct OracleConstruction {
        InPlaneAxes : Bool,
        BothBounds : Bool,
        MeasuredUnload : Bool,
        ConstantBounds : Bool,
    }
}
