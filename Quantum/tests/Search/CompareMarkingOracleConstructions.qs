namespace QuantumRayTracing.Search {
    import Std.Math.BitSizeI;
    import Std.Measurement.MeasureInteger;
    import Std.Measurement.MResetZ;

    /// # Summary
    /// Test entry: the phase the marking oracle and the reflection's S₀ give each basis state of the
    /// index register, compared between `ApplyPhaseToAllOnes` and the standard library's
    /// multi-controlled Z on a flag qubit held in |1⟩ (the construction it replaced).
    ///
    /// # Input
    /// ## count
    /// Number of indices N; every basis state of the ceil(log2 N)-qubit register is tried.
    /// ## marked
    /// Indices the oracle marks.
    ///
    /// # Output
    /// One `(oracle, reflection, clean)` triple per basis state: whether the two constructions gave
    /// the oracle the same phase, the same for S₀, and whether the register came back unchanged and
    /// every auxiliary and the flag in their starting states.
    ///
    /// # Remarks
    /// Each phase is read by kickback: a control qubit in |+⟩ applies the new construction and the
    /// adjoint of the old one, and is measured in the X basis. Equal phases leave it in |+⟩, so it
    /// reads Zero with certainty; opposite phases leave |−⟩, which reads One with certainty.
    operation CompareMarkingOracleConstructions(count : Int, marked : Int[]) : (Bool, Bool, Bool)[] {
        let width = BitSizeI(count - 1);
        mutable results = [];
        for state in 0..(1 <<< width) - 1 {
            use index = Qubit[width];
            use auxiliaries = Qubit[PhaseAuxiliaryCount(width)];
            use flag = Qubit();
            use control = Qubit();
            ApplyXorInPlace(state, index);
            X(flag);
            let oracle = HasSamePhase(control, () => {
                Controlled ApplyMarkingOracle([control], (IdealLookupGates(), marked, index, auxiliaries));
                Controlled Adjoint ApplyMarkingOracleWithControlledZ([control], (marked, index, flag));
            });
            let reflection = HasSamePhase(control, () => {
                Controlled ApplyPhaseToAllOnes([control], (IdealLookupGates(), index, auxiliaries));
                Controlled Z([control] + index, flag);
            });
            X(flag);
            let clean = MeasureInteger(index) == state and MeasureInteger(auxiliaries) == 0 and MResetZ(flag) == Zero;
            set results += [(oracle, reflection, clean)];
        }
        results
    }

    /// # Summary
    /// Runs `action` with `control` in |+⟩ and returns whether the control came back in |+⟩.
    internal operation HasSamePhase(control : Qubit, action : () => Unit) : Bool {
        H(control);
        action();
        H(control);
        MResetZ(control) == Zero
    }
}
