namespace QuantumRayTracing.Search {
    import QuantumRayTracing.Supersampling.SetDepolarizingRate;
    import QuantumRayTracing.Supersampling.ApplyDeviceCZ;

    /// # Summary
    /// A one-qubit gate (H, X or Z) followed by depolarizing noise at the one-qubit rate.
    internal operation ApplyOneQubitGateOnDevice(oneQubit : Double, gate : Qubit => Unit, target : Qubit) : Unit {
        SetDepolarizingRate(oneQubit);
        gate(target);
    }

    /// # Summary
    /// X on every qubit of `register` whose bit of `bits` is 1 (`ApplyXorInPlace`), each followed by one-qubit noise.
    internal operation ApplyXorInPlaceOnDevice(oneQubit : Double, bits : Int, register : Qubit[]) : Unit {
        for q in 0..Length(register) - 1 {
            if (bits >>> q) &&& 1 == 1 {
                ApplyOneQubitGateOnDevice(oneQubit, X, register[q]);
            }
        }
    }

    /// # Summary
    /// `ApplyPhaseToAllOnes` gate for gate (the Toffoli ladder, its CZ, the ladder undone), each gate followed by
    /// noise at its own rate: one-qubit for the Z of a one-qubit register, two-qubit on every qubit of a CZ or CCNOT.
    internal operation ApplyPhaseToAllOnesOnDevice(oneQubit : Double, twoQubit : Double, register : Qubit[], auxiliaries : Qubit[]) : Unit {
        let width = Length(register);
        if width == 1 {
            ApplyOneQubitGateOnDevice(oneQubit, Z, register[0]);
        } elif width == 2 {
            ApplyDeviceCZ(twoQubit, register[0], register[1]);
        } elif width > 2 {
            ApplyCcnotOnDevice(twoQubit, register[0], register[1], auxiliaries[0]);
            for k in 2..width - 2 {
                ApplyCcnotOnDevice(twoQubit, auxiliaries[k - 2], register[k], auxiliaries[k - 1]);
            }
            ApplyDeviceCZ(twoQubit, auxiliaries[width - 3], register[width - 1]);
            for k in width - 2..-1..2 {
                ApplyCcnotOnDevice(twoQubit, auxiliaries[k - 2], register[k], auxiliaries[k - 1]);
            }
            ApplyCcnotOnDevice(twoQubit, register[0], register[1], auxiliaries[0]);
        }
    }

    /// # Summary
    /// CCNOT followed by two-qubit-gate noise on each of its three qubits.
    internal operation ApplyCcnotOnDevice(twoQubit : Double, control1 : Qubit, control2 : Qubit, target : Qubit) : Unit {
        SetDepolarizingRate(twoQubit);
        CCNOT(control1, control2, target);
    }
}
