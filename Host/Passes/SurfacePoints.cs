using QuantumRayTracing.Shading;

namespace QuantumRayTracing.Passes;

/// <summary>The points a render shades: those primary rays found first, then those mirrors show (from <see cref="PrimaryCount"/> on).</summary>
public sealed record SurfacePoints(List<SurfacePoint> Points, int PrimaryCount)
{
    public int Count => Points.Count;

    public SurfacePoint this[int k] => Points[k];
}
