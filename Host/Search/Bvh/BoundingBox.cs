using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Search.Bvh;

/// <summary>An axis-aligned box in world units, as a BVH node bounds its primitives.</summary>
public readonly record struct BoundingBox(Vec3 Min, Vec3 Max)
{
    /// <summary>
    /// How far a primitive's box reaches past its kind's bounds on every side. A quantised hit point may sit a snap
    /// tolerance outside a rectangle (<see cref="Intersection.RayTable.SnapTolerance"/>), and a node must never
    /// cull a hit that brute force accepts.
    /// </summary>
    public const double Margin = 1e-6;

    public static BoundingBox Empty => new(new Vec3(double.PositiveInfinity, double.PositiveInfinity, double.PositiveInfinity),
        new Vec3(double.NegativeInfinity, double.NegativeInfinity, double.NegativeInfinity));

    /// <summary>The box of primitive bounds (<see cref="Intersection.PrimitiveRows.Bounds"/>), widened by <see cref="Margin"/>.</summary>
    public static BoundingBox Of((Vec3 Min, Vec3 Max) bounds) =>
        new(bounds.Min - new Vec3(Margin, Margin, Margin), bounds.Max + new Vec3(Margin, Margin, Margin));

    public BoundingBox Union(BoundingBox other) => new(
        new Vec3(Math.Min(Min.X, other.Min.X), Math.Min(Min.Y, other.Min.Y), Math.Min(Min.Z, other.Min.Z)),
        new Vec3(Math.Max(Max.X, other.Max.X), Math.Max(Max.Y, other.Max.Y), Math.Max(Max.Z, other.Max.Z)));

    public Vec3 Centre => 0.5 * (Min + Max);

    /// <summary>Surface area, the SAH's measure of how likely a random ray is to hit the box (0 when empty).</summary>
    public double Area
    {
        get
        {
            var d = Max - Min;
            return d.X < 0 || d.Y < 0 || d.Z < 0 ? 0 : 2 * (d.X * d.Y + d.Y * d.Z + d.Z * d.X);
        }
    }

    /// <summary>
    /// The slab test: the ray's parameter range inside the box, clipped to [<paramref name="tMin"/>, <paramref name="tMax"/>],
    /// or null when the ray misses it there.
    /// </summary>
    public (double Enter, double Exit)? Clip(Vec3 origin, Vec3 inverseDirection, double tMin, double tMax)
    {
        for (var axis = 0; axis < 3; axis++)
        {
            var (near, far) = ((Min[axis] - origin[axis]) * inverseDirection[axis], (Max[axis] - origin[axis]) * inverseDirection[axis]);
            if (double.IsNaN(near) || double.IsNaN(far))
            {
                // Parallel to this slab's planes (0 · ∞): inside the slab or never in it.
                if (origin[axis] < Min[axis] || origin[axis] > Max[axis]) return null;
                continue;
            }
            if (near > far) (near, far) = (far, near);
            tMin = Math.Max(tMin, near);
            tMax = Math.Min(tMax, far);
            if (tMin > tMax) return null;
        }
        return (tMin, tMax);
    }
}
