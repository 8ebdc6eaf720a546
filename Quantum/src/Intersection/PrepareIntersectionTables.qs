namespace QuantumRayTracing.Intersection {
    import Std.Convert.IntAsBoolArray;
    import Std.Convert.IntAsBigInt;
    import Std.Math.BitSizeI;

    /// # Summary
    /// Checks one ray's input and turns it into the bit tables the oracle loads.
    ///
    /// # Input
    /// ## input
    /// The ray's bounds, points, validity, depths and window constants.
    ///
    /// # Output
    /// The tables, one entry per primitive, and the comparator constants as BigInt.
    function PrepareIntersectionTables(input : IntersectionInput) : IntersectionTables {
        let count = Length(input.Bounds);
        let (c, d) = (input.CoordinateBits, input.DepthBits);
        if count < 1 {
            fail "the oracle needs at least one primitive";
        }
        if c < 1 or c > 30 or d < 1 or d > 30 {
            fail $"register widths out of range: {c} coordinate bits, {d} depth bits";
        }
        if Length(input.Points) != count or Length(input.Valid) != count or Length(input.Depths) != count {
            fail $"the table has {Length(input.Points)} points, {Length(input.Valid)} validity bits and {Length(input.Depths)} depths for {count} primitives";
        }
        let indexBits = BitSizeI(count - 1);
        if input.Near < 0 or input.Near > 1 <<< d {
            fail $"near {input.Near} is outside 0..2^{d}";
        }
        if input.Limit < 0 or input.Limit > 1 <<< (d + indexBits) {
            fail $"limit {input.Limit} is outside 0..2^{d + indexBits}";
        }
        mutable load = [];
        mutable minsToMaxes = [[], size = 3];
        mutable nextAxis = [[], size = 2];
        mutable unload = [];
        for p in 0..count - 1 {
            let (bounds, point, depth) = (input.Bounds[p], input.Points[p], input.Depths[p]);
            if Length(bounds) != 6 or Length(point) != 3 {
                fail $"row {p}: expected 6 bounds and 3 coordinates, got {Length(bounds)} and {Length(point)}";
            }
            for axis in 0..2 {
                let (low, high, at) = (bounds[2 * axis], bounds[2 * axis + 1], point[axis]);
                if low < 0 or low > high or high >= 1 <<< c or at < 0 or at >= 1 <<< c {
                    fail $"row {p}, axis {axis}: point {at} and bounds {low}..{high} must lie in 0..2^{c} - 1 with min ≤ max";
                }
            }
            if depth < 0 or depth >= 1 <<< d {
                fail $"row {p}: depth {depth} does not fit {d} bits";
            }
            let bits = value -> IntAsBoolArray(value, c);
            set load += [bits(point[0]) + bits(bounds[0]) + IntAsBoolArray(depth, d) + [input.Valid[p]]];
            for axis in 0..2 {
                set minsToMaxes w/= axis <- minsToMaxes[axis] + [bits(bounds[2 * axis] ^^^ bounds[2 * axis + 1])];
            }
            for axis in 0..1 {
                let step = bits(point[axis] ^^^ point[axis + 1]) + bits(bounds[2 * axis + 1] ^^^ bounds[2 * axis + 2]);
                set nextAxis w/= axis <- nextAxis[axis] + [step];
            }
            set unload += [bits(point[2]) + bits(bounds[5]) + IntAsBoolArray(depth, d)];
        }
        new IntersectionTables {
            IndexBits = indexBits,
            CoordinateBits = c,
            DepthBits = d,
            Load = load,
            MinsToMaxes = minsToMaxes,
            NextAxis = nextAxis,
            Unload = unload,
            Near = IntAsBigInt(input.Near),
            Limit = IntAsBigInt(input.Limit),
        }
    }
}
