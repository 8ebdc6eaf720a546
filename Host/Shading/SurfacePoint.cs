using QuantumRayTracing.Passes;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Shading;

/// <summary>
/// A point a pixel's colour depends on: a hit, the normal of its primitive facing the ray that found
/// it, and the share of the pixel's colour it carries (1 − mirror for the primary hit, mirror for
/// the reflected one).
/// </summary>
/// <remarks>
/// A render holds one per hit until shading, so the unit normal is kept in single precision: 64 bytes a point instead
/// of 80 (docs/rendering.md, large renders). An axis normal (a rectangle's) is exact in single precision.
/// </remarks>
public readonly record struct SurfacePoint
{
    private readonly float _x;
    private readonly float _y;
    private readonly float _z;

    public SurfacePoint(int pixel, Hit hit, Vec3 normal, double weight)
    {
        (Pixel, Hit, Weight) = (pixel, hit, weight);
        if (!normal.IsFinite || Math.Abs(normal.Length - 1) > 1e-6)
            throw new ArgumentException($"a surface point's normal is a unit vector, not {normal}", nameof(normal));
        (_x, _y, _z) = ((float)normal.X, (float)normal.Y, (float)normal.Z);
    }

    public int Pixel { get; }

    public Hit Hit { get; }

    /// <summary>The unit normal, facing the ray.</summary>
    public Vec3 Normal => new(_x, _y, _z);

    public double Weight { get; }

    public static SurfacePoint Of(int pixel, Ray ray, Hit hit, Primitive primitive, double weight) =>
        new(pixel, hit, FacingNormal(ray, primitive), weight);

    /// <summary>The primitive's unit normal on the side the ray comes from.</summary>
    public static Vec3 FacingNormal(Ray ray, Primitive primitive) => primitive.FacingNormal(ray.Direction);
}
