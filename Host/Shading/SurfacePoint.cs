using QuantumRayTracing.Passes;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Shading;

/// <summary>
/// A point a pixel's colour depends on: a hit, the normal of its rectangle facing the ray that found
/// it, and the share of the pixel's colour it carries (1 − mirror for the primary hit, mirror for
/// the reflected one).
/// </summary>
public readonly record struct SurfacePoint(int Pixel, Hit Hit, Vec3 Normal, double Weight)
{
    public static SurfacePoint Of(int pixel, Ray ray, Hit hit, Rectangle rectangle, double weight) =>
        new(pixel, hit, FacingNormal(ray, rectangle), weight);

    /// <summary>The rectangle's unit normal on the side the ray comes from.</summary>
    public static Vec3 FacingNormal(Ray ray, Rectangle rectangle)
    {
        var sign = ray.Direction[rectangle.FlatAxis] > 0 ? -1.0 : 1.0;
        return rectangle.FlatAxis switch
        {
            0 => new Vec3(sign, 0, 0),
            1 => new Vec3(0, sign, 0),
            _ => new Vec3(0, 0, sign),
        };
    }
}
