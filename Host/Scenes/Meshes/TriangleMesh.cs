namespace QuantumRayTracing.Scenes.Meshes;

/// <summary>
/// Vertices and the triangles that join them: what a mesh file holds once read. Every index lies in the vertex
/// list; vertices no triangle uses may be present (they count as vertices but not towards the bounds).
/// </summary>
public sealed class TriangleMesh
{
    /// <summary>The most triangles a mesh may have: 2^16, a 16-qubit index register.</summary>
    public const int MaxTriangles = 65_536;

    public TriangleMesh(IReadOnlyList<Vec3> vertices, IReadOnlyList<MeshTriangle> triangles)
    {
        foreach (var t in triangles)
            for (var k = 0; k < 3; k++)
                if ((uint)t[k] >= (uint)vertices.Count)
                    throw new ArgumentOutOfRangeException(nameof(triangles), t, $"corner index {t[k]} is outside 0..{vertices.Count - 1}");
        Vertices = vertices;
        Triangles = triangles;
    }

    public IReadOnlyList<Vec3> Vertices { get; }

    public IReadOnlyList<MeshTriangle> Triangles { get; }

    /// <summary>The position of corner <paramref name="corner"/> (0, 1 or 2) of <paramref name="triangle"/>.</summary>
    public Vec3 Corner(MeshTriangle triangle, int corner) => Vertices[triangle[corner]];

    /// <summary>The box around every triangle's corners (vertices no triangle uses are left out).</summary>
    /// <exception cref="InvalidOperationException">The mesh has no triangles.</exception>
    public (Vec3 Min, Vec3 Max) Bounds
    {
        get
        {
            if (Triangles.Count == 0) throw new InvalidOperationException("a mesh without triangles has no bounds");
            var (min, max) = (Corner(Triangles[0], 0), Corner(Triangles[0], 0));
            foreach (var t in Triangles)
                for (var k = 0; k < 3; k++)
                {
                    var v = Corner(t, k);
                    min = new Vec3(Math.Min(min.X, v.X), Math.Min(min.Y, v.Y), Math.Min(min.Z, v.Z));
                    max = new Vec3(Math.Max(max.X, v.X), Math.Max(max.Y, v.Y), Math.Max(max.Z, v.Z));
                }
            return (min, max);
        }
    }

    /// <summary>The largest side of <see cref="Bounds"/>: how far the mesh reaches along its longest axis.</summary>
    public double Extent
    {
        get
        {
            var (min, max) = Bounds;
            var size = max - min;
            return Math.Max(size.X, Math.Max(size.Y, size.Z));
        }
    }

    /// <summary>The shortest edge of any triangle that is longer than zero; 0 when every edge has length zero.</summary>
    public double SmallestEdge
    {
        get
        {
            var smallest = double.PositiveInfinity;
            foreach (var t in Triangles)
                for (var k = 0; k < 3; k++)
                {
                    var length = (Corner(t, (k + 1) % 3) - Corner(t, k)).Length;
                    if (length > 0 && length < smallest) smallest = length;
                }
            return double.IsPositiveInfinity(smallest) ? 0 : smallest;
        }
    }

    /// <summary>
    /// Whether the triangle has no area: two corners in one place or all three on a line (the cross product of two
    /// sides is exactly zero). A triangle collapsed by quantisation is one of these: on a grid of at most 16 bits
    /// the sides and their cross product are computed exactly, so "zero" there means zero.
    /// </summary>
    public bool IsDegenerate(MeshTriangle triangle)
    {
        var a = Corner(triangle, 0);
        return (Corner(triangle, 1) - a).Cross(Corner(triangle, 2) - a) == Vec3.Zero;
    }

    /// <summary>The same mesh without its degenerate triangles (<see cref="IsDegenerate"/>), and how many were dropped. The vertex list is kept as it is.</summary>
    public (TriangleMesh Mesh, int Dropped) WithoutDegenerate()
    {
        var kept = Triangles.Where(t => !IsDegenerate(t)).ToArray();
        return (kept.Length == Triangles.Count ? this : new TriangleMesh(Vertices, kept), Triangles.Count - kept.Length);
    }

    /// <summary>The same triangles on vertices moved by <paramref name="map"/>.</summary>
    public TriangleMesh MapVertices(Func<Vec3, Vec3> map) => new(Vertices.Select(map).ToArray(), Triangles);
}
