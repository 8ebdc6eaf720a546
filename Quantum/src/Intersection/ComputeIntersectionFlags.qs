namespace QuantumRayTracing.Intersection {
    import Std.Arithmetic.ApplyIfGreaterL;
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
        let (rpc, coord) = (registers.Rpc, registers.Coord);
        let c = tables.CoordinateBits;
        let (low, high) = tables.BoundRegisters == 2 ? (coord[...c - 1], coord[c...]) | (coord, coord);
        // With measured unloads the load is a plain Select, so that the oracle's uncomputation clears
        // it with the unlookup as well; otherwise it is the self-inverse XOR lookup and nothing measures.
        if tables.MeasuredUnload {
            Select(tables.Load, index, rpc + coord + registers.Depth + registers.Valid);
        } else {
            ApplyXorLookup(tables.UnitaryLookups, tables.Load, index, rpc + coord + registers.Depth + registers.Valid);
        }
        ApplyIfLessOrEqualL(X, tables.Near, registers.Depth, registers.DepthFlags[0]);
        ApplyIfGreaterL(X, tables.Limit, index + registers.Depth, registers.DepthFlags[1]);
        for s in 0..tables.Axes - 1 {
            let flag = registers.AxisFlags[s];
            if s > 0 {
                ApplyXorLookup(tables.UnitaryLookups, tables.NextAxis[s - 1], index, rpc + coord);
            }
            X(flag);
            if tables.BoundRegisters == 0 {
                let count = Length(tables.AxisBounds[s]);
                for p in 0..count - 1 {
                    let bounds = tables.AxisBounds[s][p];
                    if Length(bounds) == 2 {
                        ApplyControlledOnInt(p, ApplyIfLessOrEqualL(X, bounds[0], rpc, _), index, flag);
                        ApplyControlledOnInt(p, ApplyIfGreaterOrEqualL(X, bounds[1], rpc, _), index, flag);
                    } elif s == 0 {
                        // A row without a point, in place of a valid qubit: its first axis flag cleared.
                        ApplyControlledOnInt(p, X, index, flag);
                    }
                }
                // Indices past the last primitive hold no row either.
                if s == 0 {
                    for p in count..(1 <<< Length(index)) - 1 {
                        ApplyControlledOnInt(p, X, index, flag);
                    }
                }
            } else {
                ApplyIfLessOrEqualLE(X, low, rpc, flag);
                if tables.BoundRegisters == 1 {
                    ApplyXorLookup(tables.UnitaryLookups, tables.MinsToMaxes[s], index, coord);
                }
                ApplyIfGreaterOrEqualLE(X, high, rpc, flag);
            }
        }
        if tables.MeasuredUnload {
            Adjoint Select(tables.Unload, index, rpc + coord + registers.Depth);
        } else {
            ApplyXorLookup(tables.UnitaryLookups, tables.Unload, index, rpc + coord + registers.Depth);
        }
    }
}
