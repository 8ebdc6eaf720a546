namespace QuantumRayTracing.Intersection {
    import Std.Convert.IntAsBoolArray;
    import Std.Convert.IntAsBigInt;
    import Std.Math.BitSizeI;

    /// # Summary
    /// Checks one ray's input and turns it into the bit tables the oracle loads, for the input's
    /// construction.
    ///
    /// # Input
    /// ## input
    /// The ray's bounds, points, validity, depths, window constants, flat axes and construction.
    ///
    /// # Output
    /// The tables, one entry per primitive, and the comparator constants as BigInt.
    internal function PrepareIntersectionTables(input : IntersectionInput) : IntersectionTables {
        let count = Length(input.Bounds);
        let (c, d) = (input.CoordinateBits, input.DepthBits);
        let construction = input.Construction;
        if count < 1 {
            fail "the oracle needs at least one primitive";
        }
        if c < 1 or c > 30 or d < 1 or d > 30 {
            fail $"register widths out of range: {c} coordinate bits, {d} depth bits";
        }
        if Length(input.Points) != count or Length(input.Valid) != count or Length(input.Depths) != count or Length(input.FlatAxes) != count {
            fail $"the table has {Length(input.Points)} points, {Length(input.Valid)} validity bits, {Length(input.Depths)} depths and {Length(input.FlatAxes)} flat axes for {count} primitives";
        }
        let indexBits = BitSizeI(count - 1);
        if input.Near < 0 or input.Near > 1 <<< d {
            fail $"near {input.Near} is outside 0..2^{d}";
        }
        if input.Limit < 0 or input.Limit > 1 <<< (d + indexBits) {
            fail $"limit {input.Limit} is outside 0..2^{d + indexBits}";
        }
        let axes = construction.InPlaneAxes ? 2 | 3;
        let boundRegisters = construction.ConstantBounds ? 0 | (construction.BothBounds ? 2 | 1);
        mutable load = [];
        mutable minsToMaxes = [[], size = boundRegisters == 1 ? axes | 0];
        mutable nextAxis = [[], size = axes - 1];
        mutable unload = [];
        mutable axisBounds = [[], size = boundRegisters == 0 ? axes | 0];
        for p in 0..count - 1 {
            let (bounds, point, depth, flat) = (input.Bounds[p], input.Points[p], input.Depths[p], input.FlatAxes[p]);
            if Length(bounds) != 6 or Length(point) != 3 {
                fail $"row {p}: expected 6 bounds and 3 coordinates, got {Length(bounds)} and {Length(point)}";
            }
            for axis in 0..2 {
                let (low, high, at) = (bounds[2 * axis], bounds[2 * axis + 1], point[axis]);
                if low < 0 or low > high or high >= 1 <<< c or at < 0 or at >= 1 <<< c {
                    fail $"row {p}, axis {axis}: point {at} and bounds {low}..{high} must lie in 0..2^{c} - 1 with min ≤ max";
                }
            }
            if flat < 0 or flat > 2 or bounds[2 * flat] != bounds[2 * flat + 1] {
                fail $"row {p}: flat axis {flat} must be 0, 1 or 2 with min = max there";
            }
            // Skipping the flat axis is exact only because a valid point lies on the plane.
            if input.Valid[p] and point[flat] != bounds[2 * flat] {
                fail $"row {p}: the point {point[flat]} on flat axis {flat} is off the plane {bounds[2 * flat]}";
            }
            if depth < 0 or depth >= 1 <<< d {
                fail $"row {p}: depth {depth} does not fit {d} bits";
            }
            let tested = construction.InPlaneAxes ? (flat == 0 ? [1, 2] | (flat == 1 ? [0, 2] | [0, 1])) | [0, 1, 2];
            // Named functions rather than local lambdas, so the QIR compilation (`qrt export`) resolves every call statically.
            let bits = IntAsBoolArray(_, c);
            let first = tested[0];
            let last = tested[axes - 1];
            set load += [bits(point[first]) + CoordinateBoundsBits(bounds, first, c, boundRegisters, false) + IntAsBoolArray(depth, d) + (boundRegisters == 0 ? [] | [input.Valid[p]])];
            if boundRegisters == 0 {
                for s in 0..axes - 1 {
                    // A row without a point carries no bounds: the oracle clears its flag instead.
                    let entry = input.Valid[p] ? [IntAsBigInt(bounds[2 * tested[s]]), IntAsBigInt(bounds[2 * tested[s] + 1])] | [];
                    set axisBounds w/= s <- axisBounds[s] + [entry];
                }
            }
            if boundRegisters == 1 {
                for s in 0..axes - 1 {
                    set minsToMaxes w/= s <- minsToMaxes[s] + [bits(bounds[2 * tested[s]] ^^^ bounds[2 * tested[s] + 1])];
                }
            }
            for s in 1..axes - 1 {
                let (from, to) = (tested[s - 1], tested[s]);
                let leaving = CoordinateBoundsBits(bounds, from, c, boundRegisters, true);
                let entering = CoordinateBoundsBits(bounds, to, c, boundRegisters, false);
                let step = XorBits(bits(point[from]), bits(point[to])) + XorBits(leaving, entering);
                set nextAxis w/= s - 1 <- nextAxis[s - 1] + [step];
            }
            set unload += [bits(point[last]) + CoordinateBoundsBits(bounds, last, c, boundRegisters, true) + IntAsBoolArray(depth, d)];
        }
        new IntersectionTables {
            IndexBits = indexBits,
            CoordinateBits = c,
            DepthBits = d,
            Axes = axes,
            BoundRegisters = boundRegisters,
            MeasuredUnload = construction.MeasuredUnload,
            UnitaryLookups = false,
            Load = load,
            MinsToMaxes = minsToMaxes,
            NextAxis = nextAxis,
            Unload = unload,
            AxisBounds = axisBounds,
            Near = IntAsBigInt(input.Near),
            Limit = IntAsBigInt(input.Limit),
        }
    }
}
