namespace QuantumRayTracing.Passes;

/// <summary>
/// A large array written through once as it is made, for the per-ray and per-pixel arrays a render reads before it writes
/// (hits, occluders, radiance). Such an array comes from pages the process has not touched yet: read first, a page maps the
/// shared zero page, and its first write then costs a copy-on-write fault and a TLB flush on every core running the render
/// (on a virtual machine, an interrupt to each). Written first, a page costs one ordinary fault.
/// </summary>
public static class WrittenArray
{
    public static T[] Of<T>(int length)
    {
        var array = new T[length];
        Array.Clear(array);
        return array;
    }
}
