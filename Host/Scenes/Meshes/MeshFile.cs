namespace QuantumRayTracing.Scenes.Meshes;

/// <summary>A mesh file as read: the mesh, and one line per kind of thing the reader passed over, for the caller to print.</summary>
public sealed record MeshFile(string Path, TriangleMesh Mesh, IReadOnlyList<string> Warnings);
