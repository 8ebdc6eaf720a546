namespace QuantumRayTracing.Search {
    /// # Summary
    /// Applies a phase of −1 to the all-ones state of `register` and leaves every other basis
    /// state alone: a multi-controlled Z over the register, with its auxiliaries passed in.
    ///
    /// # Input
    /// ## gates
    /// The gates to write it in: `IdealLookupGates()`, or `DeviceLookupGates` under a device noise model.
    /// ## register
    /// The qubits whose all-ones state gets the phase.
    /// ## auxiliaries
    /// At least `PhaseAuxiliaryCount(Length(register))` qubits in |0⟩; they end in |0⟩.
    ///
    /// # Remarks
    /// A ladder of Toffoli gates ANDs the first n − 1 qubits into the auxiliaries, a CZ with the
    /// last qubit applies the phase, and the ladder is undone: 2(n − 2) Toffolis and one CZ for
    /// n ≥ 3. The caller allocates the auxiliaries once for many gates; the standard library's
    /// `Controlled Z` allocates and releases its own in every gate, which costs the simulator
    /// more than the gates themselves. On an empty register the phase is global and left out.
    internal operation ApplyPhaseToAllOnes(gates : LookupGates, register : Qubit[], auxiliaries : Qubit[]) : Unit is Adj + Ctl {
        let width = Length(register);
        if Length(auxiliaries) < PhaseAuxiliaryCount(width) {
            fail $"a phase on {width} qubits needs {PhaseAuxiliaryCount(width)} auxiliaries, got {Length(auxiliaries)}";
        }
        if width == 1 {
            gates.Z(register[0]);
        } elif width == 2 {
            gates.CZ(register[0], register[1]);
        } elif width > 2 {
            within {
                gates.CCNOT(register[0], register[1], auxiliaries[0]);
                for k in 2..width - 2 {
                    gates.CCNOT(auxiliaries[k - 2], register[k], auxiliaries[k - 1]);
                }
            } apply {
                gates.CZ(auxiliaries[width - 3], register[width - 1]);
            }
        }
    }

    /// # Summary
    /// The number of auxiliary qubits `ApplyPhaseToAllOnes` needs for a register of `width` qubits.
    internal function PhaseAuxiliaryCount(width : Int) : Int {
        width > 2 ? width - 2 | 0
    }
}
