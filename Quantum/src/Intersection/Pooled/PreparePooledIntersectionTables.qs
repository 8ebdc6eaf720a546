namespace QuantumRayTracing.Intersection {
    import Std.Convert.IntAsBoolArray;
    import Std.Math.BitSizeI;
    import Std.Math.MaxI;

    /// # Summary
    /// Checks a pool's searches and turns them into the tables of one pooled query: every ray's rows
    /// side by side in one table over the pair register, its window in a table over the rays.
    ///
    /// # Input
    /// ## inputs
    /// One ray's search each, all over the same primitives (bounds and flat axes), grid and construction.
    ///
    /// # Output
    /// The pool's tables.
    ///
    /// # Remarks
    /// A row's point, validity and depth depend on the ray as well as the primitive (the ray/plane
    /// point), so the rows are a table of Rays · 2^PrimitiveBits entries: a lookup over the pair costs
    /// what Rays lookups over one ray's table cost. Only the window depends on the ray alone.
    internal function PreparePooledIntersectionTables(inputs : IntersectionInput[]) : PooledIntersectionTables {
        let rays = Length(inputs);
        if rays < 1 {
            fail "a pool needs at least one ray";
        }
        // Each ray's own checks: its rows, and a window clamped to its own depth bits, which the wider pool register keeps exact.
        for input in inputs {
            let _ = PrepareIntersectionTables(input);
        }
        let first = inputs[0];
        let count = Length(first.Bounds);
        for k in 1..rays - 1 {
            if not SamePrimitives(inputs[k], first) {
                fail $"ray {k} of the pool searches other primitives, another grid or another construction than ray 0";
            }
        }
        let primitiveBits = BitSizeI(MaxI(count - 1, 0));
        mutable widest = 0;
        for input in inputs {
            set widest = MaxI(widest, input.DepthBits);
        }
        let d = widest + 1;
        let blank = (1 <<< primitiveBits) - count;
        mutable bounds = [];
        mutable points = [];
        mutable valid = [];
        mutable depths = [];
        mutable flats = [];
        mutable windows = [];
        for input in inputs {
            // Addresses past the last primitive: rows without a point, on a plane of x = 0.
            set bounds += input.Bounds + Repeated([0, 0, 0, 0, 0, 0], blank);
            set points += input.Points + Repeated([0, 0, 0], blank);
            set valid += input.Valid + Repeated(false, blank);
            set depths += input.Depths + Repeated(0, blank);
            set flats += input.FlatAxes + Repeated(0, blank);
            set windows += [IntAsBoolArray(input.Near, d) + IntAsBoolArray(input.Limit, primitiveBits + d)];
        }
        let rows = PrepareIntersectionTables(new IntersectionInput {
            ...first,
            DepthBits = d,
            Bounds = bounds,
            Points = points,
            Valid = valid,
            Depths = depths,
            FlatAxes = flats,
            Near = 0,
            Limit = 0,
        });
        new PooledIntersectionTables {
            Rows = rows,
            Windows = windows,
            Primitives = count,
            Rays = rays,
            PrimitiveBits = primitiveBits,
            RayBits = BitSizeI(rays - 1),
            DepthBits = d,
        }
    }

    /// # Summary
    /// Whether two searches are over the same primitives (bounds and flat axes), grid and construction.
    internal function SamePrimitives(a : IntersectionInput, b : IntersectionInput) : Bool {
        mutable same = a.CoordinateBits == b.CoordinateBits and Length(a.Bounds) == Length(b.Bounds);
        let (x, y) = (a.Construction, b.Construction);
        set same = same and x.InPlaneAxes == y.InPlaneAxes and x.BothBounds == y.BothBounds and x.MeasuredUnload == y.MeasuredUnload and x.ConstantBounds == y.ConstantBounds;
        for p in 0..(same ? Length(a.Bounds) - 1 | -1) {
            set same = same and a.FlatAxes[p] == b.FlatAxes[p] and Length(a.Bounds[p]) == Length(b.Bounds[p]);
            for k in 0..(same ? Length(a.Bounds[p]) - 1 | -1) {
                set same = same and a.Bounds[p][k] == b.Bounds[p][k];
            }
        }
        same
    }
}
