namespace QuantumRayTracing.Intersection {
    /// # Summary
    /// The bit tables `Std.TableLookup.Select` loads for one ray, one entry per primitive, built
    /// once per search by `PrepareIntersectionTables`. The rpc and coord registers go through the
    /// contents (x, minX), (x, maxX), (y, minY), (y, maxY), (z, minZ), (z, maxZ) and back to zero;
    /// each table is what one step XORs into them.
    ///
    /// # Input
    /// ## IndexBits
    /// Qubits of the index register, ceil(log2 N).
    /// ## CoordinateBits
    /// Qubits of the rpc and coord registers.
    /// ## DepthBits
    /// Qubits of the depth register.
    /// ## Load
    /// x, minX, depth, valid: loaded into rpc + coord + depth + [valid] from |0⟩.
    /// ## MinsToMaxes
    /// Per axis, min XOR max: turns coord's minimum into the maximum.
    /// ## NextAxis
    /// For X→Y and Y→Z: the point XOR the next axis's point, then the maximum XOR the next
    /// axis's minimum, for rpc + coord.
    /// ## Unload
    /// z, maxZ, depth: unloaded from rpc + coord + depth (valid stays).
    /// ## Near
    /// The near comparator's constant.
    /// ## Limit
    /// The limit comparator's constant.
    struct IntersectionTables {
        IndexBits : Int,
        CoordinateBits : Int,
        DepthBits : Int,
        Load : Bool[][],
        MinsToMaxes : Bool[][][],
        NextAxis : Bool[][][],
        Unload : Bool[][],
        Near : BigInt,
        Limit : BigInt,
    }
}
