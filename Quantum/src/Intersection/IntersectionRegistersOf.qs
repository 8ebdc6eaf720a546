namespace QuantumRayTracing.Intersection {
    import Std.Arrays.Partitioned;

    /// # Summary
    /// Splits one block of `IntersectionWorkQubits(tables)` qubits into the oracle's registers, so
    /// that callers allocate (and a test measures) the work registers as one array.
    ///
    /// # Input
    /// ## tables
    /// The ray's tables, which set the register widths.
    /// ## work
    /// The block of qubits.
    ///
    /// # Output
    /// The registers, in the order rpc, coord, axis flags, valid, depth, near limit.
    internal function IntersectionRegistersOf(tables : IntersectionTables, work : Qubit[]) : IntersectionRegisters {
        if Length(work) != IntersectionWorkQubits(tables) {
            fail $"expected {IntersectionWorkQubits(tables)} work qubits, got {Length(work)}";
        }
        let c = tables.CoordinateBits;
        let parts = Partitioned([c, tables.BoundRegisters * c, tables.Axes, ValidQubits(tables), tables.DepthBits], work);
        new IntersectionRegisters {
            Rpc = parts[0],
            Coord = parts[1],
            AxisFlags = parts[2],
            Valid = parts[3],
            Depth = parts[4],
            DepthFlags = parts[5],
        }
    }
}
