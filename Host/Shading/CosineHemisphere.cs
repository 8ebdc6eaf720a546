using QuantumRayTracing.Randomness;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Shading;

/// <summary>
/// Stratified cosine-weighted directions about an axis-aligned unit normal: density cos θ / π over the
/// hemisphere, so the mean over such directions of incoming radiance times π estimates irradiance
/// with no cosine left (docs/rendering.md, indirect light). Direction s of <c>count</c> comes from
/// cell s of <see cref="Strata.Split"/> over (φ / 2π, sin²θ), jittered by two numbers of its own
/// stream: the same index points into the same part of the hemisphere at every pixel, which lets
/// neighbour gathering compare like with like.
/// </summary>
public static class CosineHemisphere
{
    public static Vec3 Direction(Vec3 normal, int sample, int count, SeededRandom random)
    {
        var (columns, rows) = Strata.Split(count);
        var ju = random.NextDouble();
        var jv = random.NextDouble();
        var (u, v) = Strata.Point(sample, columns, rows, ju, jv);
        var phi = 2 * Math.PI * u;
        var (sinTheta, cosTheta) = (Math.Sqrt(v), Math.Sqrt(1 - v));
        var (t1, t2) = Tangents(normal);
        return cosTheta * normal + sinTheta * Math.Cos(phi) * t1 + sinTheta * Math.Sin(phi) * t2;
    }

    /// <summary>Two unit axes perpendicular to an axis-aligned normal (the scene's surfaces are axis-aligned), in increasing axis order.</summary>
    public static (Vec3, Vec3) Tangents(Vec3 normal) =>
        Math.Abs(normal.X) > 0.5 ? (new Vec3(0, 1, 0), new Vec3(0, 0, 1))
        : Math.Abs(normal.Y) > 0.5 ? (new Vec3(1, 0, 0), new Vec3(0, 0, 1))
        : (new Vec3(1, 0, 0), new Vec3(0, 1, 0));
}
