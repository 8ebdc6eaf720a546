using QuantumRayTracing.Intersection;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Passes;

/// <summary>
/// A ray's current closest hit (the paper's rt_info): the primitive, its quantised depth (the order
/// the search minimises) and the unquantised point, for shading.
/// </summary>
public readonly record struct Hit(int Primitive, int Depth, double Distance, Vec3 Point)
{
    public static Hit From(RayTable table, int primitive) =>
        new(primitive, table.Depth(primitive), table.Distance(primitive), table.Ray.At(table.Distance(primitive)));
}
