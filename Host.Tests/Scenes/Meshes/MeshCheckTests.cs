using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Tests.Scenes.Meshes;

/// <summary>`scenes check` on mesh files beside scene files: warnings, summaries and errors each where they belong.</summary>
public sealed class MeshCheckTests : IDisposable
{
    private readonly ScratchDirectory _directory = new("qrt-mesh-check-");

    public void Dispose() => _directory.Dispose();

    [Fact]
    public void AMeshAScenesAndABadMeshTogether()
    {
        var quad = _directory.File("quad.OBJ");
        File.WriteAllText(quad, "o quad\nv 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\n");
        var bad = _directory.File("bad.obj");
        File.WriteAllText(bad, "v 0 0 0\nf 1 1 1\n");
        var scene = new FileInfo(Path.Combine(RepositoryPaths.Scenes, "qornell-8.json"));
        var (output, errors) = (new StringWriter(), new StringWriter());

        Assert.Equal(1, SceneCheck.Run([new FileInfo(quad), scene, new FileInfo(bad)], output, errors));

        // Extent 2: I = 2 (1 < 2 ≤ 3); smallest edge 2: F = 1 (2 < 4 ≤ 4). Every corner is on the 2.1 grid.
        Assert.Equal(
            $"{quad}: ok: mesh, 4 vertices, 2 triangles, 0 degenerate dropped (0 of zero area, 0 collapsed on the grid), bounds (0, 0, 0)..(2, 2, 0), " +
            "2.1 fixed-point grid 0..3.5 in steps of 0.5 (moved by (0, 0, 0); smallest edge 2 = 4 steps), largest vertex displacement 0 (0 steps)",
            output.ToString().Split(Environment.NewLine)[0]);
        Assert.Contains("8 rectangles", output.ToString().Split(Environment.NewLine)[1]);
        Assert.Equal(
            $"warning: {quad}: ignored 2 lines the mesh reader does not use (o ×1, vn ×1; the first at line 1): only v and f lines are read{Environment.NewLine}" +
            $"error: {bad}: triangles: the only triangle has zero area{Environment.NewLine}",
            errors.ToString());
    }
}
