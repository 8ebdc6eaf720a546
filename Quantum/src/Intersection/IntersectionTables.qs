namespace QuantumRayTracing.Intersection {
    /// # Summary
    /// The bit tables `Std.TableLookup.Select` loads for one ray, one entry per primitive, built
    /// once per search by `PrepareIntersectionTables`. Each primitive's tested axes are visited in
    /// order (x, y, z, or only the two in its plane); the rpc and coord registers hold the point
    /// and the bounds on the axis being tested, and each table is what one step XORs into them.
    ///
    /// # Input
    /// ## IndexBits
    /// Qubits of the index register, ceil(log2 N).
    /// ## CoordinateBits
    /// Qubits of the rpc register and of each bound register.
    /// ## DepthBits
    /// Qubits of the depth register.
    /// ## Axes
    /// Axes tested per primitive: 3, or 2 when the flat axis is skipped.
    /// ## BoundRegisters
    /// 1: coord holds the minimum, then the maximum. 2: coord holds both. 0: coord is empty and the
    /// bounds are the constants of `AxisBounds`.
    /// ## MeasuredUnload
    /// Whether `Load` is cleared by measurement (`Adjoint Select`) or by a second lookup.
    /// ## UnitaryLookups
    /// Whether the lookups uncompute their ANDs by Toffoli gates instead of by measurement and
    /// feedback (`ApplyXorLookup`): set for circuits exported to formats without feedback.
    /// ## Load
    /// The first tested axis's point and bound(s), the depth and the validity bit (none with constant
    /// bounds), loaded into rpc + coord + depth + valid from |0⟩.
    /// ## MinsToMaxes
    /// Per tested axis, min XOR max: turns coord's minimum into the maximum (one bound register
    /// only; empty otherwise).
    /// ## NextAxis
    /// Per step to the next tested axis: the point XOR the next point for rpc, then the bound(s)
    /// held XOR the next axis's minimum (and maximum) for coord.
    /// ## Unload
    /// The last tested axis's point and bound(s) and the depth, cleared from rpc + coord + depth
    /// (valid stays).
    /// ## AxisBounds
    /// With no bound register: per tested axis step, per primitive, [minimum, maximum] on that axis,
    /// or [] for a row without a point (the whole array is empty with bound registers).
    /// ## Near
    /// The near comparator's constant.
    /// ## Limit
    /// The limit comparator's constant.
    internal struct IntersectionTables {
        IndexBits : Int,
        CoordinateBits : Int,
        DepthBits : Int,
        Axes : Int,
        BoundRegisters : Int,
        MeasuredUnload : Bool,
        UnitaryLookups : Bool,
        Load : Bool[][],
        MinsToMaxes : Bool[][][],
        NextAxis : Bool[][][],
        Unload : Bool[][],
        AxisBounds : BigInt[][][],
        Near : BigInt,
        Limit : BigInt,
    }
}
