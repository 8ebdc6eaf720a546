namespace QuantumRayTracing.Intersection {
    /// # Summary
    /// The elementwise XOR of two bit strings of equal length: what turns one loaded value into another.
    ///
    /// # Input
    /// ## a
    /// First bit string.
    /// ## b
    /// Second bit string, as long as `a`.
    ///
    /// # Output
    /// a[k] XOR b[k] for every k.
    internal function XorBits(a : Bool[], b : Bool[]) : Bool[] {
        if Length(a) != Length(b) {
            fail $"cannot XOR bit strings of lengths {Length(a)} and {Length(b)}";
        }
        mutable result = [];
        for k in 0..Length(a) - 1 {
            set result += [a[k] != b[k]];
        }
        result
    }
}
