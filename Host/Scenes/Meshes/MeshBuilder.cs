namespace QuantumRayTracing.Scenes.Meshes;

/// <summary>
/// Collects a reader's vertices and triangles with the checks every mesh format shares: finite coordinates, at most
/// <see cref="TriangleMesh.MaxTriangles"/> triangles, at least one. Each check names the file and the element the
/// reader passes (an OBJ line, a glTF primitive).
/// </summary>
internal sealed class MeshBuilder(string file)
{
    private readonly List<Vec3> _vertices = [];
    private readonly List<MeshTriangle> _triangles = [];

    public int VertexCount => _vertices.Count;

    /// <returns>The vertex's index.</returns>
    public int AddVertex(Vec3 vertex, string element)
    {
        if (!vertex.IsFinite) throw new MeshError(file, element, NotFinite(vertex));
        _vertices.Add(vertex);
        return _vertices.Count - 1;
    }

    public void AddTriangle(int a, int b, int c, string element)
    {
        if (_triangles.Count == TriangleMesh.MaxTriangles)
            throw new MeshError(file, element, $"more than {TriangleMesh.MaxTriangles} triangles; a mesh may have at most {TriangleMesh.MaxTriangles} (a 16-qubit index register)");
        _triangles.Add(new MeshTriangle(a, b, c));
    }

    /// <summary>The problem of a vertex with a NaN or infinite coordinate, in every format's errors.</summary>
    public static string NotFinite(Vec3 vertex) => $"vertex {vertex} is not finite; every coordinate must be a finite number (no NaN or infinity)";

    public TriangleMesh Build(string element) => _triangles.Count == 0
        ? throw new MeshError(file, element, "no triangles: a mesh needs at least one")
        : new TriangleMesh(_vertices.ToArray(), _triangles.ToArray());
}
