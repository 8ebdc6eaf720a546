namespace QuantumRayTracing.Intersection {
    /// # Summary
    /// What one pooled query loads, built once per pool by `PreparePooledIntersectionTables`: the rows
    /// of every (ray, primitive) pair as one table addressed by the pair register, and each ray's window
    /// as a table addressed by its ray part.
    ///
    /// # Input
    /// ## Rows
    /// The pairs' tables: ray k's row for primitive p at address k · 2^PrimitiveBits + p (the pair
    /// register's primitive part low, its ray part high); each ray's addresses past the last primitive
    /// hold rows without a point. Its `Near` and `Limit` are unused: the window is loaded.
    /// ## Windows
    /// Per ray, its near (`DepthBits` bits) then its limit (`PrimitiveBits + DepthBits` bits), little-endian.
    /// ## Primitives
    /// Number of primitives N.
    /// ## Rays
    /// Number of rays in the pool.
    /// ## PrimitiveBits
    /// Qubits of the pair register's primitive part, ceil(log2 N).
    /// ## RayBits
    /// Qubits of its ray part, ceil(log2 Rays).
    /// ## DepthBits
    /// Qubits of the depth register: one more than the widest ray's, so that every ray's clamped
    /// window fits (a near of 2^d accepts nothing, a limit of 2^(n + d) every row).
    internal struct PooledIntersectionTables {
        Rows : IntersectionTables,
        Windows : Bool[][],
        Primitives : Int,
        Rays : Int,
        PrimitiveBits : Int,
        RayBits : Int,
        DepthBits : Int,
    }
}
