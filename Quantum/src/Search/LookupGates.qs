namespace QuantumRayTracing.Search {
    /// # Summary
    /// The gates the lookup search is written in, passed down so that one circuit serves the ideal search
    /// (`IdealLookupGates`, the simulator's own gates) and the search under a device noise model
    /// (`DeviceLookupGates`, each gate preceded by its own depolarizing rate).
    internal struct LookupGates {
        H : Qubit => Unit is Adj + Ctl,
        X : Qubit => Unit is Adj + Ctl,
        Z : Qubit => Unit is Adj + Ctl,
        CZ : (Qubit, Qubit) => Unit is Adj + Ctl,
        CCNOT : (Qubit, Qubit, Qubit) => Unit is Adj + Ctl,
        PrepareUniform : (Int, Qubit[]) => Unit is Adj + Ctl,
    }

    /// # Summary
    /// The simulator's own gates and `PrepareUniformSuperposition`: the ideal lookup search.
    internal function IdealLookupGates() : LookupGates {
        new LookupGates { H = H, X = X, Z = Z, CZ = CZ, CCNOT = CCNOT, PrepareUniform = PrepareUniformSuperposition }
    }

    /// # Summary
    /// X on every qubit of `register` whose bit of `bits` is 1, as `ApplyXorInPlace`, with the given X gate.
    internal operation ApplyXorWith(x : Qubit => Unit is Adj + Ctl, bits : Int, register : Qubit[]) : Unit is Adj + Ctl {
        for q in 0..Length(register) - 1 {
            if (bits >>> q) &&& 1 == 1 {
                x(register[q]);
            }
        }
    }
}
