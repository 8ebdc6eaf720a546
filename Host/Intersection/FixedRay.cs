using QuantumRayTracing.Rays;

namespace QuantumRayTracing.Intersection;

/// <summary>
/// A ray on a fixed-point grid finer than the scene's, for the exact triangle test (<see cref="TriangleRows"/>): the
/// origin in units of 2^−<see cref="OriginFractionBits"/> grid steps, and the direction scaled so its principal
/// component is ±2^<see cref="DirectionBits"/>, each rounded to the nearest integer. The rounding moves the ray by
/// less than 2^−8 of a grid step over 2^15 steps of travel; every triangle of a scene sees the same fixed ray.
/// </summary>
public readonly record struct FixedRay(long Ox, long Oy, long Oz, long Dx, long Dy, long Dz)
{
    /// <summary>R: fraction bits of the origin below a grid step.</summary>
    public const int OriginFractionBits = 8;

    /// <summary>S: the direction's principal component is 2^S.</summary>
    public const int DirectionBits = 24;

    /// <summary>
    /// The largest origin coordinate, in fine units: 2^40, so every corner less the origin stays below 2^42 and the
    /// edge functions' products fit 128 bits (grid integers are below 2^16).
    /// </summary>
    public const long MaxOrigin = 1L << 40;

    /// <summary>|Dx| + |Dy| + |Dz|.</summary>
    public double Norm1 => Math.Abs((double)Dx) + Math.Abs((double)Dy) + Math.Abs((double)Dz);

    /// <summary>The fixed form of <paramref name="ray"/> on a grid of <paramref name="scale"/> integers per world unit; null when its origin lies beyond <see cref="MaxOrigin"/>.</summary>
    public static FixedRay? Of(Ray ray, double scale)
    {
        var fine = scale * (1 << OriginFractionBits);
        var (origin, direction) = (ray.Origin, ray.Direction);
        var (x, y, z) = (Math.Round(origin.X * fine), Math.Round(origin.Y * fine), Math.Round(origin.Z * fine));
        if (!(Math.Abs(x) <= MaxOrigin && Math.Abs(y) <= MaxOrigin && Math.Abs(z) <= MaxOrigin)) return null;
        var largest = Math.Max(Math.Abs(direction.X), Math.Max(Math.Abs(direction.Y), Math.Abs(direction.Z)));
        if (!(largest > 0) || !double.IsFinite(largest)) return null;
        var unit = (double)(1L << DirectionBits) / largest;
        return new FixedRay((long)x, (long)y, (long)z,
            (long)Math.Round(direction.X * unit), (long)Math.Round(direction.Y * unit), (long)Math.Round(direction.Z * unit));
    }
}
