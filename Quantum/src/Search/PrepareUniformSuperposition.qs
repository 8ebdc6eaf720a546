namespace QuantumRayTracing.Search {
    import Std.Math.ArcCos;
    import Std.Math.Sqrt;
    import Std.Convert.IntAsDouble;

    /// # Summary
    /// Prepares the uniform superposition over the first `count` basis states of `register`,
    /// leaving every basis state at or above `count` with amplitude exactly zero.
    ///
    /// # Input
    /// ## count
    /// Number of basis states in the superposition, 1 ≤ count ≤ 2^Length(register).
    /// ## register
    /// Little-endian index register in |0…0⟩.
    ///
    /// # Remarks
    /// A power-of-two `count` costs one H per qubit. Otherwise the top qubit is rotated so that
    /// it is |0⟩ with probability 2^(n-1)/count, the lower half is spread by H gates under the
    /// top qubit's |0⟩, and the remaining `count - 2^(n-1)` states are prepared recursively under
    /// its |1⟩. The preparation is exact, so Grover's success probability is sin²((2r+1)θ) with
    /// sin²θ = t/count, not t/2^n.
    internal operation PrepareUniformSuperposition(count : Int, register : Qubit[]) : Unit is Adj + Ctl {
        let width = Length(register);
        if count < 1 or count > 1 <<< width {
            fail $"count {count} does not fit a register of {width} qubits";
        }
        if count == 1 <<< width {
            ApplyToEachCA(H, register);
        } else {
            let lowerHalf = 1 <<< (width - 1);
            let lower = register[...width - 2];
            let top = register[width - 1];
            if count <= lowerHalf {
                PrepareUniformSuperposition(count, lower);
            } else {
                Ry(2.0 * ArcCos(Sqrt(IntAsDouble(lowerHalf) / IntAsDouble(count))), top);
                within { X(top); } apply { Controlled ApplyToEachCA([top], (H, lower)); }
                Controlled PrepareUniformSuperposition([top], (count - lowerHalf, lower));
            }
        }
    }
}
