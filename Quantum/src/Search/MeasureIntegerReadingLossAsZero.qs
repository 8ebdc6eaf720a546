namespace QuantumRayTracing.Search {
    import Std.Measurement.IsLossResult;

    /// # Summary
    /// Measures a little-endian register as an integer and resets it, reading a lost qubit as Zero,
    /// as a device that cannot see a missing qubit reads it dark.
    ///
    /// # Input
    /// ## register
    /// The qubits to measure, least significant first.
    ///
    /// # Output
    /// The integer read; without qubit loss the same as `MeasureInteger`.
    internal operation MeasureIntegerReadingLossAsZero(register : Qubit[]) : Int {
        mutable value = 0;
        for k in 0..Length(register) - 1 {
            if MeasureBitReadingLossAsZero(register[k]) {
                set value += 1 <<< k;
            }
        }
        value
    }

    /// # Summary
    /// Measures one qubit and resets it: true for One, false for Zero or a lost qubit.
    internal operation MeasureBitReadingLossAsZero(qubit : Qubit) : Bool {
        let result = MResetZ(qubit);
        not IsLossResult(result) and result == One
    }
}
