namespace QuantumRayTracing.Intersection {
    import Std.Arithmetic.ApplyIfGreaterL;
    import Std.Arithmetic.ApplyIfGreaterOrEqualLE;
    import Std.Arithmetic.ApplyIfLessOrEqualL;
    import Std.Arithmetic.ApplyIfLessOrEqualLE;
    import Std.TableLookup.Select;

    /// # Summary
    /// Computes the six flags whose AND is i_r(p) for every primitive p in the index register:
    /// valid, i_X, i_Y, i_Z (paper fig. 4, one axis after another), near and limit (fig. 5).
    /// Every other register is back in |0⟩ afterwards.
    ///
    /// # Input
    /// ## tables
    /// The ray's tables, from `PrepareIntersectionTables`.
    /// ## index
    /// Index register (`tables.IndexBits` qubits), holding indices below the primitive count.
    /// ## registers
    /// The work registers, all in |0⟩.
    ///
    /// # Remarks
    /// Axis flags use the paper's XOR trick: the flag starts at 1 and each of min ≤ rpc and
    /// max ≥ rpc flips it. Because min ≤ max, the two cannot both fail, so the flag ends at 1
    /// exactly when both hold. An AND would need a second flag qubit per axis and a Toffoli, or
    /// controlled comparators; the trick needs neither.
    ///
    /// The lookups dominate the cost (each touches every row), so the figure's load/unload pairs
    /// are fused: one lookup loads X's point and minimum with the depth and validity, each later
    /// step XORs the change into the loaded registers (minimum to maximum, then on to the next
    /// axis), and one measurement-based unlookup clears them: 6 lookups and 1 unlookup instead of
    /// a load and an unload per value (11 and 10), on the same registers.
    ///
    /// The limit comparator reads the index register as the low bits and the depth register as
    /// the high bits of one number, so one comparison against a constant gives the lexicographic
    /// (depth, id) order.
    operation ComputeIntersectionFlags(tables : IntersectionTables, index : Qubit[], registers : IntersectionRegisters) : Unit is Adj {
        let (rpc, coord) = (registers.Rpc, registers.Coord);
        Select(tables.Load, index, rpc + coord + registers.Depth + [registers.Valid]);
        ApplyIfLessOrEqualL(X, tables.Near, registers.Depth, registers.DepthFlags[0]);
        ApplyIfGreaterL(X, tables.Limit, index + registers.Depth, registers.DepthFlags[1]);
        for axis in 0..2 {
            let flag = registers.AxisFlags[axis];
            if axis > 0 {
                ApplyXorLookup(tables.NextAxis[axis - 1], index, rpc + coord);
            }
            X(flag);
            ApplyIfLessOrEqualLE(X, coord, rpc, flag);
            ApplyXorLookup(tables.MinsToMaxes[axis], index, coord);
            ApplyIfGreaterOrEqualLE(X, coord, rpc, flag);
        }
        Adjoint Select(tables.Unload, index, rpc + coord + registers.Depth);
    }
}
