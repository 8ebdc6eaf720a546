using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Shading;

/// <summary>The rays a hit spawns: the mirror reflection and the shadow ray to a light.</summary>
public static class SecondaryRays
{
    /// <summary>The reflection of <paramref name="ray"/> at <paramref name="point"/>, leaving the mirror it hit.</summary>
    public static Ray Specular(Ray ray, SurfacePoint point)
    {
        var d = ray.Direction;
        var reflected = d - 2 * d.Dot(point.Normal) * point.Normal;
        return new Ray(point.Hit.Point, reflected, ExcludedPrimitive: point.Hit.Primitive);
    }

    /// <summary>
    /// The segment from <paramref name="point"/> to <paramref name="light"/> (t = 1 at the light, the
    /// exact end), or null when the light is behind the surface and cannot light it, so no ray is traced.
    /// </summary>
    public static Ray? Shadow(SurfacePoint point, PointLight light)
    {
        var toLight = light.Position - point.Hit.Point;
        if (toLight.Dot(point.Normal) <= 0) return null;
        return new Ray(point.Hit.Point, toLight, MaxDistance: 1.0, ExcludedPrimitive: point.Hit.Primitive);
    }
}
