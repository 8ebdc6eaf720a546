namespace QuantumRayTracing.Rendering;

/// <summary>
/// A forced, compacting full collection between a large render and its classical reference, handing back the memory the
/// render's tiles no longer need: their
/// per-ray arrays are large objects, which the runtime frees only in a full collection (docs/rendering.md, large renders).
/// Small renders skip it: a full collection would cost them more than it saves.
/// </summary>
public static class LargeRenderCollection
{
    /// <summary>Collects when a render of <paramref name="pixels"/> is large (<see cref="RenderForecast.LargePixels"/>); does nothing otherwise.</summary>
    public static void Collect(long pixels)
    {
        if (pixels < RenderForecast.LargePixels) return;
        System.Runtime.GCSettings.LargeObjectHeapCompactionMode = System.Runtime.GCLargeObjectHeapCompactionMode.CompactOnce;
        GC.Collect(GC.MaxGeneration, GCCollectionMode.Forced, blocking: true, compacting: true);
    }
}
