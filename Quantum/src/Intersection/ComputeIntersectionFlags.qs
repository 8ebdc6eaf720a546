namespace QuantumRayTracing.Intersection {
    import Std.Arithmetic.ApplyIfGreaterL;
    import Std.Arithmetic.ApplyIfGreaterLE;
    import Std.Arithmetic.ApplyIfGreaterOrEqualLE;
    import Std.Arithmetic.ApplyIfLessOrEqualL;
    import Std.Arithmetic.ApplyIfLessOrEqualLE;
    import Std.Arithmetic.ApplyIfGreaterOrEqualL;
    import Std.TableLookup.Select;

    /// # Summary
    /// Computes the flags whose AND is i_r(p) for every primitive p in the index register: valid,
    /// one flag per tested axis (paper fig. 4, one axis after another), near and limit (fig. 5).
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
    /// are fused: one lookup loads the first axis's point and bounds with the depth and validity,
    /// each later step XORs the change into the loaded registers (minimum to maximum, then on to
    /// the next axis), and one unlookup clears them. With all three axes and one bound register
    /// that is 6 lookups and 1 unlookup instead of a load and an unload per value (11 and 10);
    /// testing only the two in-plane axes with both bounds loaded at once needs 2 lookups and
    /// 1 unlookup (`OracleConstruction`).
    ///
    /// With no bound register (`ConstantBounds`) each axis step compares the point with every
    /// primitive's minimum and maximum as constants, each comparison controlled on the index
    /// register holding that primitive: the same XOR trick, with no bound loaded. Validity is then
    /// a classical fact per primitive too: a row without a point (and an index past the last
    /// primitive) gets its first axis flag cleared under index control, and no valid qubit is held.
    ///
    /// The limit comparator reads the index register as the low bits and the depth register as
    /// the high bits of one number, so one comparison against a constant gives the lexicographic
    /// (depth, id) order.
    internal operation ComputeIntersectionFlags(tables : IntersectionTables, index : Qubit[], registers : IntersectionRegisters) : Unit is Adj {
        ComputeWindowedIntersectionFlags(tables, index, index, [], [], registers);
    }

    /// # Summary
    /// `ComputeIntersectionFlags` with the rows read at `address` and the window either the tables'
    /// constants or loaded into registers: the one-ray oracle passes its index for both and no window
    /// register; a pooled query (`ComputePooledIntersectionFlags`) the pair register as the address,
    /// its primitive part for the limit's tie-break, and the window its ray's lookup loaded.
    ///
    /// # Input
    /// ## tables
    /// The rows' tables, one row per address.
    /// ## address
    /// The lookups' address register (`tables.IndexBits` qubits).
    /// ## primitive
    /// The primitive id the limit comparator reads below the depth.
    /// ## near
    /// The window's near as a register as wide as the depth register (compared by depth ≥ near), or
    /// empty: then `tables.Near`, a constant.
    /// ## limit
    /// The window's limit over primitive + depth read as one number, or empty: then `tables.Limit`.
    /// ## registers
    /// The work registers, all in |0⟩.
    internal operation ComputeWindowedIntersectionFlags(tables : IntersectionTables, address : Qubit[], primitive : Qubit[], near : Qubit[], limit : Qubit[], registers : IntersectionRegisters) : Unit is Adj {
        let (rpc, coord) = (registers.Rpc, registers.Coord);
        let c = tables.CoordinateBits;
        let (low, high) = tables.BoundRegisters == 2 ? (coord[...c - 1], coord[c...]) | (coord, coord);
        // With measured unloads the load is a plain Select, so that the oracle's uncomputation clears
        // it with the unlookup as well; otherwise it is the self-inverse XOR lookup and nothing measures.
        if tables.MeasuredUnload {
            Select(tables.Load, address, rpc + coord + registers.Depth + registers.Valid);
        } else {
            ApplyXorLookup(tables.UnitaryLookups, tables.Load, address, rpc + coord + registers.Depth + registers.Valid);
        }
        if Length(near) == 0 {
            ApplyIfLessOrEqualL(X, tables.Near, registers.Depth, registers.DepthFlags[0]);
            ApplyIfGreaterL(X, tables.Limit, primitive + registers.Depth, registers.DepthFlags[1]);
        } else {
            ApplyIfLessOrEqualLE(X, near, registers.Depth, registers.DepthFlags[0]);
            ApplyIfGreaterLE(X, limit, primitive + registers.Depth, registers.DepthFlags[1]);
        }
        for s in 0..tables.Axes - 1 {
            let flag = registers.AxisFlags[s];
            if s > 0 {
                ApplyXorLookup(tables.UnitaryLookups, tables.NextAxis[s - 1], address, rpc + coord);
            }
            X(flag);
            if tables.BoundRegisters == 0 {
                let count = Length(tables.AxisBounds[s]);
                for p in 0..count - 1 {
                    let bounds = tables.AxisBounds[s][p];
                    if Length(bounds) == 2 {
                        ApplyControlledOnInt(p, ApplyIfLessOrEqualL(X, bounds[0], rpc, _), address, flag);
                        ApplyControlledOnInt(p, ApplyIfGreaterOrEqualL(X, bounds[1], rpc, _), address, flag);
                    } elif s == 0 {
                        // A row without a point, in place of a valid qubit: its first axis flag cleared.
                        ApplyControlledOnInt(p, X, address, flag);
                    }
                }
                // Indices past the last primitive hold no row either.
                if s == 0 {
                    for p in count..(1 <<< Length(address)) - 1 {
                        ApplyControlledOnInt(p, X, address, flag);
                    }
                }
            } else {
                ApplyIfLessOrEqualLE(X, low, rpc, flag);
                if tables.BoundRegisters == 1 {
                    ApplyXorLookup(tables.UnitaryLookups, tables.MinsToMaxes[s], address, coord);
                }
                ApplyIfGreaterOrEqualLE(X, high, rpc, flag);
            }
        }
        if tables.MeasuredUnload {
            Adjoint Select(tables.Unload, address, rpc + coord + registers.Depth);
        } else {
            ApplyXorLookup(tables.UnitaryLookups, tables.Unload, address, rpc + coord + registers.Depth);
        }
    }
}
