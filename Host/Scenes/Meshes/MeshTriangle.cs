namespace QuantumRayTracing.Scenes.Meshes;

/// <summary>One triangle of a <see cref="TriangleMesh"/>: the indices of its three corners in the mesh's vertex list (0-based).</summary>
public readonly record struct MeshTriangle(int A, int B, int C)
{
    /// <summary>Corner 0, 1 or 2.</summary>
    public int this[int corner] => corner switch
    {
        0 => A,
        1 => B,
        2 => C,
        _ => throw new ArgumentOutOfRangeException(nameof(corner), corner, "a triangle has corners 0, 1 and 2"),
    };
}
