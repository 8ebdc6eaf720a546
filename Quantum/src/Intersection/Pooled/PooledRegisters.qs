namespace QuantumRayTracing.Intersection {
    import Std.Arrays.Partitioned;

    /// # Summary
    /// The work registers of one pooled query, all in |0⟩ between queries: the one-ray oracle's, over
    /// the pool's rows, and the window its ray's lookup loads.
    ///
    /// # Input
    /// ## Row
    /// rpc, coord, the flags, valid and depth, as in `IntersectionRegisters`.
    /// ## Near
    /// The ray's near (`DepthBits` qubits).
    /// ## Limit
    /// The ray's limit over primitive + depth (`PrimitiveBits + DepthBits` qubits).
    internal struct PooledRegisters {
        Row : IntersectionRegisters,
        Near : Qubit[],
        Limit : Qubit[],
    }

    /// # Summary
    /// How many qubits a pooled query's work registers take: the one-ray oracle's over the pool's rows,
    /// and the window's near and limit.
    internal function PooledWorkQubits(pool : PooledIntersectionTables) : Int {
        IntersectionWorkQubits(pool.Rows) + WindowQubits(pool)
    }

    /// # Summary
    /// The qubits the loaded window takes: near, then limit.
    internal function WindowQubits(pool : PooledIntersectionTables) : Int {
        pool.DepthBits + pool.PrimitiveBits + pool.DepthBits
    }

    /// # Summary
    /// Splits a block of `PooledWorkQubits(pool)` qubits into a pooled query's registers.
    internal function PooledRegistersOf(pool : PooledIntersectionTables, work : Qubit[]) : PooledRegisters {
        if Length(work) != PooledWorkQubits(pool) {
            fail $"expected {PooledWorkQubits(pool)} work qubits, got {Length(work)}";
        }
        let parts = Partitioned([IntersectionWorkQubits(pool.Rows), pool.DepthBits], work);
        new PooledRegisters {
            Row = IntersectionRegistersOf(pool.Rows, parts[0]),
            Near = parts[1],
            Limit = parts[2],
        }
    }
}
