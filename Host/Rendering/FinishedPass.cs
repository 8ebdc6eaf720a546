namespace QuantumRayTracing.Rendering;

/// <summary>
/// Hands back, between a large render's passes, the memory a finished pass no longer needs. A pass's per-ray arrays
/// are large objects, which the runtime frees only in a full collection; left to its own pacing it lets a render's
/// resident memory reach about twice what the render holds (docs/rendering.md, large renders). Small renders skip it: a
/// full collection per pass would cost them more than it saves.
/// </summary>
public static class FinishedPass
{
    public static void Release(long pixels)
    {
        if (pixels < RenderForecast.LargePixels) return;
        System.Runtime.GCSettings.LargeObjectHeapCompactionMode = System.Runtime.GCLargeObjectHeapCompactionMode.CompactOnce;
        GC.Collect(GC.MaxGeneration, GCCollectionMode.Forced, blocking: true, compacting: true);
    }
}
