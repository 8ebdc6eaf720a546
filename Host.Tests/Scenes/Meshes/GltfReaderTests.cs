using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Meshes;

namespace QuantumRayTracing.Tests.Scenes.Meshes;

public sealed class GltfReaderTests : IDisposable
{
    private readonly ScratchDirectory _directory = new("qrt-gltf-");

    public void Dispose() => _directory.Dispose();

    /// <summary>A unit square in z = 0, as two triangles (0, 1, 2) and (0, 2, 3).</summary>
    private static readonly (float, float, float)[] Square = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)];

    private static readonly ushort[] SquareIndices = [0, 1, 2, 0, 2, 3];

    /// <summary>
    /// Node 0 (translation (1, 2, 3), scale 2) maps v to 2v + (1, 2, 3); node 1, its child with translation (0, 0, 10),
    /// maps v to 2(v + (0, 0, 10)) + (1, 2, 3) = 2v + (1, 2, 23). The square's corners (0,0,0) (1,0,0) (1,1,0) (0,1,0)
    /// go to (1,2,3) (3,2,3) (3,4,3) (1,4,3) and (1,2,23) (3,2,23) (3,4,23) (1,4,23); node 2 is in no scene.
    /// </summary>
    private static readonly Vec3[] Placed =
    [
        new(1, 2, 3), new(3, 2, 3), new(3, 4, 3), new(1, 4, 3),
        new(1, 2, 23), new(3, 2, 23), new(3, 4, 23), new(1, 4, 23),
    ];

    [Theory]
    [InlineData("square.gltf")]
    [InlineData("square.glb")]
    public void NodeTransformsAreApplied(string name)
    {
        var path = GltfFixture.Write(_directory.File(name), Square, SquareIndices);
        var file = MeshReader.Read(path);
        Assert.Equal(Placed, file.Mesh.Vertices);
        Assert.Equal([new(0, 1, 2), new(0, 2, 3), new(4, 5, 6), new(4, 6, 7)], file.Mesh.Triangles);
        Assert.Equal((new Vec3(1, 2, 3), new Vec3(3, 4, 23)), file.Mesh.Bounds);
        Assert.Empty(file.Warnings);
    }

    /// <summary>A strip 0 1 3 2 is the two triangles of the square, whatever the order SharpGLTF gives their corners.</summary>
    [Fact]
    public void TriangleStripsAreSplitIntoTriangles()
    {
        var path = GltfFixture.Write(_directory.File("strip.gltf"), Square, [0, 1, 3, 2], GltfFixture.TriangleStrip);
        var mesh = MeshReader.Read(path).Mesh;
        Assert.Equal(4, mesh.Triangles.Count);
        Assert.All(mesh.Triangles, t => Assert.False(mesh.IsDegenerate(t)));
        Assert.Equal(
            [new[] { 0, 1, 3 }, new[] { 1, 2, 3 }],
            mesh.Triangles.Take(2).Select(t => new[] { t.A, t.B, t.C }.Order().ToArray()));
    }

    [Theory]
    [InlineData("lines.gltf")]
    [InlineData("lines.glb")]
    public void LinesAreRefused(string name)
    {
        var path = GltfFixture.Write(_directory.File(name), Square, [0, 1, 1, 2, 2, 3, 3, 0], GltfFixture.Lines);
        var error = Assert.Throws<MeshError>(() => MeshReader.Read(path));
        Assert.Equal($"{path}: meshes[0].primitives[0]: mode LINES (1): only triangles are read (TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN)", error.Message);
    }

    /// <summary>Named as the OBJ reader names it, at the accessor element (SharpGLTF's own check refuses the file first).</summary>
    [Theory]
    [InlineData(float.PositiveInfinity, "Infinity")]
    [InlineData(float.NaN, "NaN")]
    public void NonFinitePositionsAreRefused(float value, string shown)
    {
        var path = GltfFixture.Write(_directory.File("not-finite.glb"), [(0, 0, 0), (1, 0, 0), (0, value, 0)], [0, 1, 2]);
        var error = Assert.Throws<MeshError>(() => MeshReader.Read(path));
        // The vertex is shown as read, or as placed by node 0 (2v + (1, 2, 3)) when SharpGLTF lets the value through.
        Assert.StartsWith($"{path}: meshes[0].primitives[0].POSITION[2]: vertex (", error.Message);
        Assert.Contains($", {shown}, ", error.Message);
        Assert.EndsWith(") is not finite; every coordinate must be a finite number (no NaN or infinity)", error.Message);
    }

    [Fact]
    public void NoTrianglesIsRefused()
    {
        var path = GltfFixture.Write(_directory.File("empty.gltf"), Square, SquareIndices, meshless: true);
        var error = Assert.Throws<MeshError>(() => MeshReader.Read(path));
        Assert.StartsWith($"{path}: ", error.Message);
        Assert.Contains("no triangles", error.Message);
    }
}
