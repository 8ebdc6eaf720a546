namespace QuantumRayTracing.Supersampling {
    /// # Summary
    /// ceil(log2 count): the width of a register holding `count` ≥ 1 subpixels (0 for one).
    internal function SubpixelQubits(count : Int) : Int {
        mutable width = 0;
        while 1 <<< width < count {
            set width += 1;
        }
        width
    }
}
