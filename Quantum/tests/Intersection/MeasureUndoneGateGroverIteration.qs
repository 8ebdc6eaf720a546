namespace QuantumRayTracing.Intersection {
    import Std.Arrays.ForEach;
    import Std.Measurement.MeasureInteger;
    import QuantumRayTracing.Search.PrepareUniformSuperposition;

    /// # Summary
    /// Applies a gate-level Grover iteration G and then undoes it, through the variants a
    /// controlled search needs, and measures everything: a test that the adjoint and controlled
    /// specialisations (with their measurement-based unlookups) are exact inverses.
    ///
    /// # Input
    /// ## input
    /// The ray's bounds, table and window constants.
    /// ## variant
    /// 0: G then Adjoint G. 1: Controlled G on a control in |1⟩, then Adjoint G. 2: Controlled G on a
    /// control in |+⟩, then Controlled Adjoint G, then H on the control.
    ///
    /// # Output
    /// The measured [index, control, work registers as one integer, flag]. An exact undo gives
    /// [0, 1, 0, 1] for variant 1 and [0, 0, 0, 1] otherwise: the index returns to the uniform
    /// superposition, which the inverse preparation maps to 0, and the control is left unentangled.
    operation MeasureUndoneGateGroverIteration(input : IntersectionInput, variant : Int) : Int[] {
        let tables = PrepareIntersectionTables(input);
        let count = Length(input.Bounds);
        use index = Qubit[tables.IndexBits];
        use work = Qubit[IntersectionWorkQubits(tables)];
        use flag = Qubit();
        use control = Qubit();
        let registers = IntersectionRegistersOf(tables, work);
        X(flag);
        PrepareUniformSuperposition(count, index);
        if variant == 0 {
            ApplyGateGroverIteration(tables, count, index, registers, flag);
            Adjoint ApplyGateGroverIteration(tables, count, index, registers, flag);
        } elif variant == 1 {
            X(control);
            Controlled ApplyGateGroverIteration([control], (tables, count, index, registers, flag));
            Adjoint ApplyGateGroverIteration(tables, count, index, registers, flag);
        } elif variant == 2 {
            H(control);
            Controlled ApplyGateGroverIteration([control], (tables, count, index, registers, flag));
            Controlled Adjoint ApplyGateGroverIteration([control], (tables, count, index, registers, flag));
            H(control);
        } else {
            fail $"unknown variant {variant}";
        }
        Adjoint PrepareUniformSuperposition(count, index);
        ForEach(MeasureInteger, [index, [control], work, [flag]])
    }
}
