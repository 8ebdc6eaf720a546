namespace QuantumRayTracing.Intersection {
    import QuantumRayTracing.Search.PrepareUniformSuperposition;

    /// # Summary
    /// Prepares the uniform superposition over a pool's (ray, primitive) pairs: every primitive below
    /// `primitives` in the pair register's low `primitiveBits` qubits, every ray below `rays` in the rest.
    /// Pairs past either count keep amplitude exactly zero.
    ///
    /// # Input
    /// ## primitives
    /// Number of primitives N.
    /// ## rays
    /// Number of rays in the pool.
    /// ## primitiveBits
    /// Qubits of the primitive part.
    /// ## pair
    /// The pair register, in |0…0⟩.
    internal operation PreparePoolPairs(primitives : Int, rays : Int, primitiveBits : Int, pair : Qubit[]) : Unit is Adj + Ctl {
        PrepareUniformSuperposition(primitives, pair[...primitiveBits - 1]);
        PrepareUniformSuperposition(rays, pair[primitiveBits...]);
    }
}
