namespace QuantumRayTracing.Scenes.Meshes;

/// <summary>
/// A mesh on its <see cref="GridChoice"/> grid: every vertex a grid value, the triangles that collapsed there dropped
/// (<see cref="Collapsed"/> of them), and the largest distance a used vertex moved in the rounding.
/// </summary>
public sealed record QuantisedMesh(TriangleMesh Mesh, int Collapsed, double LargestDisplacement);
