using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Rays;

/// <summary>
/// A ray: origin and direction in world units, and the depth range it accepts, in the scene's
/// fixed-point depth units measured along <see cref="PrincipalAxis"/> from the origin (paper sec. 4.1:
/// near and far clipping lengths along the direction's principal axis).
/// </summary>
/// <param name="Origin">Where the ray starts, in world units.</param>
/// <param name="Direction">Any non-zero length; t = 1 is one direction length from the origin.</param>
/// <param name="Near">Smallest accepted depth, inclusive.</param>
/// <param name="Far">Largest accepted depth, inclusive; <see cref="Unbounded"/> for none.</param>
/// <param name="MaxDistance">Exclusive end of the ray in parameter t (a shadow ray ends at its light, t = 1); infinity for none. Exact, not quantised.</param>
/// <param name="ExcludedPrimitive">The primitive the ray leaves from (a shadow or specular ray's surface), never hit; −1 for none.</param>
public readonly record struct Ray(Vec3 Origin, Vec3 Direction, int Near = 0, int Far = Ray.Unbounded, double MaxDistance = double.PositiveInfinity, int ExcludedPrimitive = -1)
{
    public const int Unbounded = int.MaxValue;

    /// <summary>The axis along which the direction has its largest component (ties go to the lower axis).</summary>
    public int PrincipalAxis
    {
        get
        {
            var (x, y, z) = (Math.Abs(Direction.X), Math.Abs(Direction.Y), Math.Abs(Direction.Z));
            return x >= y && x >= z ? 0 : y >= z ? 1 : 2;
        }
    }

    /// <summary>The point at parameter <paramref name="t"/>: origin + t · direction.</summary>
    public Vec3 At(double t) => Origin + t * Direction;
}
