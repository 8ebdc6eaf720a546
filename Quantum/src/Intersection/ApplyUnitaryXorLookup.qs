namespace QuantumRayTracing.Intersection {
    import Std.Math.BitSizeI;

    /// # Summary
    /// XORs `data[a]` into `target` for each address a in `address` by unary iteration (Babbush et
    /// al., arXiv:1805.03662, sec. III A): the address's top bit splits the table in halves, each
    /// half is looked up under a control that holds "address in this half", recursively. Every
    /// control is computed and uncomputed by a Toffoli, so the lookup is unitary and measures nothing.
    ///
    /// # Input
    /// ## data
    /// One bit string per address, each as long as `target`.
    /// ## address
    /// Little-endian address register of at least ceil(log2 Length(data)) qubits; its higher
    /// qubits are not read.
    /// ## target
    /// Register the data is XORed into.
    internal operation ApplyUnitaryXorLookup(data : Bool[][], address : Qubit[], target : Qubit[]) : Unit is Adj {
        body (...) {
            if Length(data) == 1 {
                ApplyBitsAsX(data[0], target);
            } else {
                let (low, high, lower, top) = LookupHalves(data, address);
                within {
                    X(top);
                } apply {
                    ApplyControlledUnitaryXorLookup(top, low, lower, target);
                }
                ApplyControlledUnitaryXorLookup(top, high, lower, target);
            }
        }
        adjoint self;
    }

    /// # Summary
    /// `ApplyUnitaryXorLookup` under one control qubit: nothing happens when `control` is |0⟩.
    internal operation ApplyControlledUnitaryXorLookup(control : Qubit, data : Bool[][], address : Qubit[], target : Qubit[]) : Unit {
        if Length(data) == 1 {
            Controlled ApplyBitsAsX([control], (data[0], target));
        } else {
            let (low, high, lower, top) = LookupHalves(data, address);
            use inHalf = Qubit();
            // inHalf = control ∧ ¬top, then control ∧ top after the CNOT, then back to |0⟩.
            within {
                X(top);
            } apply {
                CCNOT(control, top, inHalf);
            }
            ApplyControlledUnitaryXorLookup(inHalf, low, lower, target);
            CNOT(control, inHalf);
            ApplyControlledUnitaryXorLookup(inHalf, high, lower, target);
            CCNOT(control, top, inHalf);
        }
    }

    /// # Summary
    /// A table of at least two rows split by its address's top bit: the rows below 2^(n−1), the
    /// rest, the address bits below the top one and the top one (n = ceil(log2 rows)).
    internal function LookupHalves(data : Bool[][], address : Qubit[]) : (Bool[][], Bool[][], Qubit[], Qubit) {
        let n = BitSizeI(Length(data) - 1);
        if Length(address) < n {
            fail $"a table of {Length(data)} rows needs {n} address qubits, got {Length(address)}";
        }
        let half = 1 <<< (n - 1);
        (data[...half - 1], data[half...], address[...n - 2], address[n - 1])
    }

    /// # Summary
    /// Applies X to each qubit of `target` whose bit in `bits` is set.
    internal operation ApplyBitsAsX(bits : Bool[], target : Qubit[]) : Unit is Adj + Ctl {
        if Length(bits) != Length(target) {
            fail $"{Length(bits)} data bits for {Length(target)} target qubits";
        }
        for k in 0..Length(target) - 1 {
            if bits[k] {
                X(target[k]);
            }
        }
    }
}
