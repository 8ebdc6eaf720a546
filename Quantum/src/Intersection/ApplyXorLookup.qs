namespace QuantumRayTracing.Intersection {
    import Std.TableLookup.Select;

    /// # Summary
    /// XORs `data[a]` into `target` for each address a in `address`: `Select` on a target that
    /// need not start in |0⟩, declared self-adjoint.
    ///
    /// # Input
    /// ## byGates
    /// Whether the lookup's ANDs are uncomputed by Toffoli gates (`ApplyUnitaryXorLookup`) instead
    /// of `Select`'s measurement and feedback: the same gates once the feedback is made unitary,
    /// without the measurements, which the QDK's QIR compile pays for (one branch each).
    /// ## data
    /// One bit string per address, each as long as `target`.
    /// ## address
    /// Little-endian address register.
    /// ## target
    /// Register the data is XORed into.
    ///
    /// # Remarks
    /// `Adjoint Select` uncomputes by measurement, which is only right when the target returns to
    /// |0…0⟩. A lookup that changes a loaded value into another (minimum into maximum) must be undone
    /// by applying it again.
    internal operation ApplyXorLookup(byGates : Bool, data : Bool[][], address : Qubit[], target : Qubit[]) : Unit is Adj {
        body (...) {
            if byGates {
                ApplyUnitaryXorLookup(data, address, target);
            } else {
                Select(data, address, target);
            }
        }
        adjoint self;
    }
}
