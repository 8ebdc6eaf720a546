namespace QuantumRayTracing.Intersection {
    import Std.TableLookup.Select;

    /// # Summary
    /// XORs `data[a]` into `target` for each address a in `address`: `Select` on a target that
    /// need not start in |0⟩, declared self-adjoint.
    ///
    /// # Input
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
    internal operation ApplyXorLookup(data : Bool[][], address : Qubit[], target : Qubit[]) : Unit is Adj + Ctl {
        body (...) {
            Select(data, address, target);
        }
        adjoint self;
    }
}
