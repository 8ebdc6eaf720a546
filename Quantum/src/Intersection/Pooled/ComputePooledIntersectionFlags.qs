namespace QuantumRayTracing.Intersection {
    import Std.TableLookup.Select;

    /// # Summary
    /// Computes, for every (ray, primitive) pair in the pair register, the flags whose AND says that
    /// the ray's row for that primitive is accepted in the ray's window: the window loaded by a lookup
    /// over the rays, the row by the one-ray oracle's lookups over the pairs, then its comparators, the
    /// near and limit ones against the loaded window. Every other register is back in |0⟩ afterwards
    /// except the window, which the caller's uncomputation clears.
    ///
    /// # Input
    /// ## pool
    /// The pool's tables, from `PreparePooledIntersectionTables`.
    /// ## pair
    /// The pair register: the primitive part (`pool.PrimitiveBits` qubits, below N) low, the ray part
    /// (`pool.RayBits` qubits, below the pool's rays) high.
    /// ## registers
    /// The work registers, all in |0⟩.
    internal operation ComputePooledIntersectionFlags(pool : PooledIntersectionTables, pair : Qubit[], registers : PooledRegisters) : Unit is Adj {
        if Length(pair) != pool.PrimitiveBits + pool.RayBits {
            fail $"the pair register has {Length(pair)} qubits; {pool.Rays} rays of {pool.Primitives} primitives need {pool.PrimitiveBits + pool.RayBits}";
        }
        let primitive = pair[...pool.PrimitiveBits - 1];
        let ray = pair[pool.PrimitiveBits...];
        let window = registers.Near + registers.Limit;
        // The window is cleared as the rows are: by the unlookup when they are, by a second lookup otherwise.
        if pool.Rows.MeasuredUnload {
            Select(pool.Windows, ray, window);
        } else {
            ApplyXorLookup(pool.Rows.UnitaryLookups, pool.Windows, ray, window);
        }
        ComputeWindowedIntersectionFlags(pool.Rows, pair, primitive, registers.Near, registers.Limit, registers.Row);
    }
}
