namespace QuantumRayTracing.Intersection {
    import Std.Arrays.Zipped;
    import Std.Diagnostics.CheckAllZero;

    /// # Summary
    /// The pooled query in XOR form on every basis state (ray k, primitive p) of each pool at once, against the expected
    /// outputs: `CheckIntersectionOracleOnEveryRow` for the pair register.
    ///
    /// # Description
    /// A label register holds the uniform superposition over the pool's pairs and the pair register a copy of it; the query
    /// runs on the pair register. Each branch keeps its own label, so the branches cannot interfere: the output, XORed with
    /// the expected output of the label's pair, and the pair register, XORed with the label, must end as |0⟩ in every
    /// branch, with every work register; and the label, prepared back, as |0⟩, which it does only if no branch was lost to
    /// a measurement or left with a phase of its own.
    ///
    /// # Input
    /// ## pools
    /// Per pool, one ray's search each, over the same primitives.
    /// ## expected
    /// Per pool, per ray, per primitive, whether the ray's row for that primitive is accepted in its window.
    ///
    /// # Output
    /// Per pool, true if every check held.
    operation CheckPooledQueryOnEveryPair(pools : IntersectionInput[][], expected : Bool[][][]) : Bool[] {
        mutable results = [];
        for k in 0..Length(pools) - 1 {
            let pool = PreparePooledIntersectionTables(pools[k]);
            if Length(expected[k]) != pool.Rays {
                fail $"pool {k}: expected outputs for {Length(expected[k])} rays, the pool has {pool.Rays}";
            }
            let width = pool.PrimitiveBits + pool.RayBits;
            use label = Qubit[width];
            use pair = Qubit[width];
            use work = Qubit[PooledWorkQubits(pool)];
            use output = Qubit();
            PreparePoolPairs(pool.Primitives, pool.Rays, pool.PrimitiveBits, label);
            for (l, i) in Zipped(label, pair) {
                CNOT(l, i);
            }
            ApplyPooledIntersectionOracle(pool, pair, PooledRegistersOf(pool, work), output);
            for ray in 0..pool.Rays - 1 {
                if Length(expected[k][ray]) != pool.Primitives {
                    fail $"pool {k}, ray {ray}: {Length(expected[k][ray])} expected outputs for {pool.Primitives} primitives";
                }
                for p in 0..pool.Primitives - 1 {
                    if expected[k][ray][p] {
                        ApplyControlledOnInt((ray <<< pool.PrimitiveBits) + p, X, label, output);
                    }
                }
            }
            for (l, i) in Zipped(label, pair) {
                CNOT(l, i);
            }
            mutable clean = CheckAllZero([output] + pair + work);
            if clean {
                Adjoint PreparePoolPairs(pool.Primitives, pool.Rays, pool.PrimitiveBits, label);
                set clean = CheckAllZero(label);
            }
            set results += [clean];
            ResetAll(label + pair + work + [output]);
        }
        results
    }
}
