namespace QuantumRayTracing.Intersection {
    import Std.Convert.IntAsBoolArray;

    /// # Summary
    /// What the coord register holds while one axis of a primitive is tested: with two bound
    /// registers its minimum and maximum (minimum first); with one, its minimum when the axis is
    /// entered and its maximum when it is left.
    ///
    /// # Input
    /// ## bounds
    /// The primitive's [minX, maxX, minY, maxY, minZ, maxZ].
    /// ## axis
    /// The tested axis, 0, 1 or 2.
    /// ## coordinateBits
    /// Bits per coordinate.
    /// ## boundRegisters
    /// 1 or 2 (`IntersectionTables.BoundRegisters`).
    /// ## leaving
    /// Whether the axis's test is done (one bound register then holds the maximum).
    ///
    /// # Output
    /// The register's bits, little-endian per coordinate.
    internal function CoordinateBoundsBits(bounds : Int[], axis : Int, coordinateBits : Int, boundRegisters : Int, leaving : Bool) : Bool[] {
        let low = IntAsBoolArray(bounds[2 * axis], coordinateBits);
        let high = IntAsBoolArray(bounds[2 * axis + 1], coordinateBits);
        boundRegisters == 2 ? low + high | (boundRegisters == 1 ? (leaving ? high | low) | [])
    }
}
