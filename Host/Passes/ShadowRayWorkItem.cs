using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Shading;

namespace QuantumRayTracing.Passes;

/// <summary>
/// A shadow ray queued for the shadow pass: from surface point <paramref name="Point"/> towards light <paramref name="Light"/>
/// (the scene's point lights first, then its directional lights). Only the two indices are kept; the ray, its pixel and its layout
/// channel are computed when the pass reads them.
/// </summary>
public readonly record struct ShadowRayWorkItem(int Point, int Light)
{
    /// <summary>Whether the point has a shadow ray towards the light at all (the light in front of its surface).</summary>
    public static bool Exists(Scene scene, SurfacePoints points, int point, int light) => light < scene.Lights.Count
        ? SecondaryRays.HasShadow(points[point], scene.Lights[light])
        : SecondaryRays.HasDirectional(points[point], scene.DirectionalLights[light - scene.Lights.Count]);

    public Ray Ray(Scene scene, SurfacePoints points) => (Light < scene.Lights.Count
        ? SecondaryRays.Shadow(points[Point], scene.Lights[Light])
        : SecondaryRays.TowardsDirectional(points[Point], scene.DirectionalLights[Light - scene.Lights.Count], scene.Grid))!.Value;

    public int Pixel(SurfacePoints points) => points[Point].Pixel;

    /// <summary>The light, and whether the point is primary or reflected: gathering compares rays towards the same light from the same kind of point.</summary>
    public int Channel(SurfacePoints points) => 2 * Light + (Point < points.PrimaryCount ? 0 : 1);
}
