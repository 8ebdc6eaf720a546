namespace QuantumRayTracing.Intersection {
    /// # Summary
    /// One ray's search as the host describes it: the scene's bounds, the ray's lookup table and
    /// the two comparator constants of its hit window, all as grid integers.
    ///
    /// # Input
    /// ## CoordinateBits
    /// Qubits of a coordinate register (the scene grid's bits).
    /// ## DepthBits
    /// Qubits of the depth register; every depth is below 2^DepthBits.
    /// ## Bounds
    /// One row per primitive: [minX, maxX, minY, maxY, minZ, maxZ], with min ≤ max on every axis.
    /// ## Points
    /// One row per primitive: the quantised ray/plane point [x, y, z], each in 0..2^CoordinateBits − 1
    /// (an invalid row may hold any such point).
    /// ## Valid
    /// Whether each row holds a ray/plane point at all.
    /// ## Depths
    /// Each row's quantised depth along the ray's principal axis.
    /// ## Near
    /// Smallest accepted depth, clamped by the host to 0..2^DepthBits.
    /// ## Limit
    /// LimitDepth · 2^IndexBits + LimitId, clamped by the host to 0..2^(DepthBits + IndexBits): a row
    /// is accepted when Depth · 2^IndexBits + p is below it.
    /// ## FlatAxes
    /// Each primitive's flat axis (0, 1 or 2): its minimum and maximum there are its plane, and a
    /// valid row's point lies on that plane.
    /// ## Construction
    /// How the oracle is built; every construction marks the same rows.
    struct IntersectionInput {
        CoordinateBits : Int,
        DepthBits : Int,
        Bounds : Int[][],
        Points : Int[][],
        Valid : Bool[],
        Depths : Int[],
        Near : Int,
        Limit : Int,
        FlatAxes : Int[],
        Construction : OracleConstruction,
    }
}
