using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Shading;

/// <summary>
/// Area lights seen directly by a camera or mirror ray. They are not primitives, so no search finds
/// them: the renderer checks each such ray against the (few) emitters classically, and a ray that
/// crosses one before its hit shows the emitter's exitance π · radiance — the same units as a diffuse
/// surface's albedo · irradiance (docs/rendering.md). These checks are not ray/primitive tests and are
/// not counted in #C_Int.
/// </summary>
public static class Emitters
{
    /// <summary>
    /// The exitance of the nearest area light <paramref name="ray"/> crosses at 0 &lt; t ≤ <paramref name="limit"/>
    /// (a light in the plane of the hit surface wins the tie), or null.
    /// </summary>
    public static Vec3? Seen(Ray ray, double limit, IReadOnlyList<AreaLight> lights)
    {
        Vec3? seen = null;
        var nearest = limit;
        foreach (var light in lights)
        {
            var along = ray.Direction[light.FlatAxis];
            if (Math.Abs(along) < 1e-12) continue;
            var t = (light.Min[light.FlatAxis] - ray.Origin[light.FlatAxis]) / along;
            if (!(t > RayTable.SnapTolerance) || t > nearest) continue;
            var point = ray.At(t);
            var (u, v) = light.PlaneAxes;
            if (point[u] < light.Min[u] || point[u] > light.Max[u] || point[v] < light.Min[v] || point[v] > light.Max[v]) continue;
            nearest = t;
            seen = Math.PI * light.Radiance;
        }
        return seen;
    }
}
