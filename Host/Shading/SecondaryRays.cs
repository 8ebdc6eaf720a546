using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Shading;

/// <summary>The rays a hit spawns: the mirror reflection, shadow rays to lights and VPL rays.</summary>
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
        if (!InFront(toLight, point)) return null;
        return new Ray(point.Hit.Point, toLight, MaxDistance: 1.0, ExcludedPrimitive: point.Hit.Primitive);
    }

    /// <summary>Whether <see cref="Shadow"/> gives a ray, without building it.</summary>
    public static bool HasShadow(SurfacePoint point, PointLight light) => InFront(light.Position - point.Hit.Point, point);

    /// <summary>Whether <see cref="TowardsDirectional"/> gives a ray, without building it.</summary>
    public static bool HasDirectional(SurfacePoint point, DirectionalLight light) => InFront(-light.Direction, point);

    // Whether a ray along `toward` leaves the surface on the side its normal faces (as "not behind": a NaN counts as in front).
    private static bool InFront(Vec3 toward, SurfacePoint point) => !(toward.Dot(point.Normal) <= 0);

    /// <summary>The segment from <paramref name="point"/> to <paramref name="target"/> (exact end t = 1 there), or null when the target is not in front of the surface.</summary>
    public static Ray? Towards(SurfacePoint point, Vec3 target)
    {
        var toTarget = target - point.Hit.Point;
        if (!InFront(toTarget, point)) return null;
        return new Ray(point.Hit.Point, toTarget, MaxDistance: 1.0, ExcludedPrimitive: point.Hit.Primitive);
    }

    /// <summary>
    /// The ray from <paramref name="point"/> back along a directional light's direction, ending exactly
    /// where it leaves the grid's cube [0, 2^integerBits]³ (every primitive lies inside), or null when the
    /// light comes from behind the surface.
    /// </summary>
    public static Ray? TowardsDirectional(SurfacePoint point, DirectionalLight light, CoordinateGrid grid)
    {
        var toLight = -light.Direction;
        if (!InFront(toLight, point)) return null;
        var extent = grid.Max + grid.Step;
        var exit = double.PositiveInfinity;
        for (var axis = 0; axis < 3; axis++)
        {
            if (toLight[axis] > 0) exit = Math.Min(exit, (extent - point.Hit.Point[axis]) / toLight[axis]);
            else if (toLight[axis] < 0) exit = Math.Min(exit, -point.Hit.Point[axis] / toLight[axis]);
        }
        return new Ray(point.Hit.Point, toLight, MaxDistance: Math.Max(0, exit), ExcludedPrimitive: point.Hit.Primitive);
    }

    /// <summary>A VPL ray: from <paramref name="point"/> along <paramref name="direction"/>, leaving its surface, unbounded.</summary>
    public static Ray Bounce(SurfacePoint point, Vec3 direction) =>
        new(point.Hit.Point, direction, ExcludedPrimitive: point.Hit.Primitive);
}
