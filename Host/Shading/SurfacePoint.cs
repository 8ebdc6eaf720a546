using QuantumRayTracing.Passes;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Shading;

/// <summary>
/// A point a pixel's colour depends on: a hit, the normal of its rectangle facing the ray that found
/// it, and the share of the pixel's colour it carries (1 − mirror for the primary hit, mirror for
/// the reflected one).
/// </summary>
/// <remarks>
/// A render holds one per hit until shading, so the normal, a unit vector along one axis (every primitive is an
/// axis-aligned rectangle), is kept as a byte: 56 bytes a point instead of 80 (docs/rendering.md, large renders).
/// </remarks>
public readonly record struct SurfacePoint
{
    private readonly sbyte _normal; // ±(axis + 1)

    public SurfacePoint(int pixel, Hit hit, Vec3 normal, double weight)
    {
        (Pixel, Hit, Weight) = (pixel, hit, weight);
        _normal = Encode(normal);
    }

    public int Pixel { get; }

    public Hit Hit { get; }

    /// <summary>The unit normal, along one axis.</summary>
    public Vec3 Normal => (Math.Abs(_normal) - 1, _normal > 0 ? 1.0 : -1.0) switch
    {
        (0, var sign) => new Vec3(sign, 0, 0),
        (1, var sign) => new Vec3(0, sign, 0),
        (_, var sign) => new Vec3(0, 0, sign),
    };

    public double Weight { get; }

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

    private static sbyte Encode(Vec3 normal)
    {
        var axis = Math.Abs(normal.X) == 1 ? 0 : Math.Abs(normal.Y) == 1 ? 1 : 2;
        var zeros = (normal.X == 0 ? 1 : 0) + (normal.Y == 0 ? 1 : 0) + (normal.Z == 0 ? 1 : 0);
        if (Math.Abs(normal[axis]) != 1 || zeros != 2)
            throw new ArgumentException($"a surface point's normal is a unit vector along one axis, not {normal}", nameof(normal));
        return (sbyte)(normal[axis] > 0 ? axis + 1 : -(axis + 1));
    }
}
