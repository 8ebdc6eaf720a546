using QuantumRayTracing.Intersection;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Passes;

/// <summary>
/// A ray's current closest hit (the paper's rt_info): the primitive, its quantised depth (the order
/// the search minimises) and the unquantised point, for shading.
/// </summary>
public readonly record struct Hit(int Primitive, int Depth, double Distance, Vec3 Point)
{
    /// <summary>
    /// The window of a search for something better than <paramref name="current"/> on <paramref name="ray"/>:
    /// closer under <paramref name="tieBreak"/>, or the ray's whole range while it has no hit.
    /// </summary>
    public static HitWindow Beyond(Rays.Ray ray, Hit? current, int count, TieBreak tieBreak) => current is { } hit
        ? HitWindow.Closer(ray.Near, hit.Depth, hit.Primitive, tieBreak)
        : HitWindow.Range(ray.Near, ray.Far, count);

    public static Hit From(RayTable table, int primitive) =>
        new(primitive, table.Depth(primitive), table.Distance(primitive), table.Ray.At(table.Distance(primitive)));
}
