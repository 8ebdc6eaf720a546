using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Tests.Intersection;

/// <summary>Scenes of triangles (and rectangles) built in code, on a 5-bit integer grid unless told, for the triangle tests.</summary>
internal static class TriangleScenes
{
    public static readonly Material White = new("white", new Vec3(0.7, 0.7, 0.7), 0);

    public static Triangle Tri(int id, Vec3 a, Vec3 b, Vec3 c) => new(id, a, b, c, White);

    /// <summary>A scene holding <paramref name="primitives"/> (ids in order), one light above, the camera at <paramref name="eye"/> looking at <paramref name="at"/>.</summary>
    public static Scene With(IReadOnlyList<Primitive> primitives, Vec3? eye = null, Vec3? at = null, int size = 16, CoordinateGrid? grid = null) =>
        new("triangles", size, size, grid ?? new CoordinateGrid(5, 0), new Camera(eye ?? new Vec3(16, 16, -8), at ?? new Vec3(16, 16, 16), new Vec3(0, 1, 0), 60),
            0.1, [White], [new PointLight(new Vec3(16, 30, 4), new Vec3(300, 300, 300))], primitives);

    /// <summary>The square [lo, hi]² at z = <paramref name="z"/> cut along its diagonal into two triangles, ids from <paramref name="first"/>.</summary>
    public static Triangle[] SplitSquare(double lo, double hi, double z, int first = 0) =>
    [
        Tri(first, new Vec3(lo, lo, z), new Vec3(hi, lo, z), new Vec3(hi, hi, z)),
        Tri(first + 1, new Vec3(lo, lo, z), new Vec3(hi, hi, z), new Vec3(lo, hi, z)),
    ];

    /// <summary>
    /// The same square as a fan of eight triangles around its centre, through the corners and the edges' midpoints,
    /// the corners' order alternating so the fan's triangles do not share a winding.
    /// </summary>
    public static Triangle[] Fan(double lo, double hi, double z, int first = 0)
    {
        var mid = (lo + hi) / 2;
        Vec3[] rim = [new(lo, lo, z), new(mid, lo, z), new(hi, lo, z), new(hi, mid, z), new(hi, hi, z), new(mid, hi, z), new(lo, hi, z), new(lo, mid, z)];
        var centre = new Vec3(mid, mid, z);
        return [.. Enumerable.Range(0, 8).Select(k => k % 2 == 0
            ? Tri(first + k, centre, rim[k], rim[(k + 1) % 8])
            : Tri(first + k, rim[(k + 1) % 8], centre, rim[k]))];
    }

    /// <summary>A four-sided pyramid over [lo, hi]² at z = <paramref name="z"/> with its apex at height <paramref name="apex"/> (towards −z), ids from 0.</summary>
    public static Triangle[] Pyramid(double lo, double hi, double z, double apex)
    {
        var mid = (lo + hi) / 2;
        var top = new Vec3(mid, mid, apex);
        Vec3[] rim = [new(lo, lo, z), new(hi, lo, z), new(hi, hi, z), new(lo, hi, z)];
        return [.. Enumerable.Range(0, 4).Select(k => Tri(k, top, rim[k], rim[(k + 1) % 4]))];
    }
}
