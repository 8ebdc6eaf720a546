namespace QuantumRayTracing.Estimation {
    import Std.ResourceEstimation.*;

    /// # Summary
    /// Stands for a circuit whose logical counts are already known, so that the Resource Estimator
    /// prices those counts directly instead of tracing the circuit again.
    ///
    /// # Input
    /// ## qubits
    /// Peak logical qubits of the circuit.
    /// ## tGates
    /// T gates.
    /// ## rotations
    /// Single-qubit rotations.
    /// ## rotationDepth
    /// Rotation depth.
    /// ## cczGates
    /// CCZ gates.
    /// ## measurements
    /// Single-qubit measurements.
    ///
    /// # Remarks
    /// The counts are taken as counted before layout, as the estimator counts a traced program, and
    /// laid out with its default (PSSPC) layout.
    operation AccountForLogicalCounts(qubits : Int, tGates : Int, rotations : Int, rotationDepth : Int, cczGates : Int, measurements : Int) : Unit {
        use register = Qubit[qubits];
        AccountForEstimates(
            [TCount(tGates), RotationCount(rotations), RotationDepth(rotationDepth), CczCount(cczGates), MeasurementCount(measurements)],
            PSSPCLayout(),
            register
        );
    }
}
