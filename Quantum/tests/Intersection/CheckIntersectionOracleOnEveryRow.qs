namespace QuantumRayTracing.Intersection {
    import Std.Arrays.Zipped;
    import Std.Diagnostics.CheckAllZero;
    import Std.StatePreparation.PrepareUniformSuperposition;

    /// # Summary
    /// The XOR form of the oracle on every basis state p < N of each input at once, against the expected outputs.
    ///
    /// # Description
    /// A label register holds the uniform superposition of p < N (the standard library's preparation) and the index a copy
    /// of it; the oracle runs on the index. Each branch p keeps its own label, which the oracle does not touch, so the
    /// branches cannot interfere: the output, XORed with the expected output of the label's row, and the index, XORed with
    /// the label, must end as |0⟩ in every branch, with every work register; and the label, prepared back, as |0⟩, which it
    /// does only if no branch was lost to a measurement or left with a phase of its own (a failure of the preparation's
    /// adjoint is a runtime error).
    ///
    /// # Input
    /// ## inputs
    /// One ray's search each.
    /// ## expected
    /// Per input, per row p, the output verify-rpc gives.
    ///
    /// # Output
    /// Per input, true if every check held.
    operation CheckIntersectionOracleOnEveryRow(inputs : IntersectionInput[], expected : Bool[][]) : Bool[] {
        mutable results = [];
        for k in 0..Length(inputs) - 1 {
            let tables = PrepareIntersectionTables(inputs[k]);
            let count = Length(inputs[k].Bounds);
            if Length(expected[k]) != count {
                fail $"input {k}: {Length(expected[k])} expected outputs for {count} rows";
            }
            use label = Qubit[tables.IndexBits];
            use index = Qubit[tables.IndexBits];
            use work = Qubit[IntersectionWorkQubits(tables)];
            use output = Qubit();
            PrepareUniformSuperposition(count, label);
            for (l, i) in Zipped(label, index) {
                CNOT(l, i);
            }
            ApplyIntersectionOracle(tables, index, IntersectionRegistersOf(tables, work), output);
            for p in 0..count - 1 {
                if expected[k][p] {
                    ApplyControlledOnInt(p, X, label, output);
                }
            }
            for (l, i) in Zipped(label, index) {
                CNOT(l, i);
            }
            mutable clean = CheckAllZero([output] + index + work);
            if clean {
                // Every branch is back to |p⟩ on the label alone; the preparation's adjoint fails on its auxiliary
                // qubit, as a runtime error, where the branches are no longer the uniform superposition.
                Adjoint PrepareUniformSuperposition(count, label);
                set clean = CheckAllZero(label);
            }
            set results += [clean];
            ResetAll(label + index + work + [output]);
        }
        results
    }
}
