using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Meshes;

namespace QuantumRayTracing.Tests.Scenes.Meshes;

public sealed class ObjReaderTests
{
    private static MeshFile Parse(string text) => ObjReader.Parse(new StringReader(text), "test.obj");

    private static (int, int, int)[] Triangles(MeshFile file) => file.Mesh.Triangles.Select(t => (t.A, t.B, t.C)).ToArray();

    [Fact]
    public void ATriangle()
    {
        var file = Parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        Assert.Equal([new Vec3(0, 0, 0), new Vec3(1, 0, 0), new Vec3(0, 1, 0)], file.Mesh.Vertices);
        Assert.Equal([(0, 1, 2)], Triangles(file));
        Assert.Empty(file.Warnings);
    }

    /// <summary>A quad fans from its first corner into (1,2,3) and (1,3,4); a pentagon into three triangles.</summary>
    [Fact]
    public void PolygonsAreFannedFromTheirFirstCorner()
    {
        const string square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
        Assert.Equal([(0, 1, 2), (0, 2, 3)], Triangles(Parse(square + "f 1 2 3 4\n")));
        var pentagon = Parse(square + "v 0.5 1.5 0\nf 1 2 3 5 4\n");
        Assert.Equal([(0, 1, 2), (0, 2, 4), (0, 4, 3)], Triangles(pentagon));
    }

    /// <summary>−1 is the last vertex read so far: after 4 vertices, −4..−1 are vertices 1..4, and later faces see later vertices.</summary>
    [Fact]
    public void NegativeIndicesCountBackFromTheLastVertexSoFar()
    {
        var file = Parse("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf -4 -3 -2\nv 5 5 5\nf -1 -2 -3\nf 1 -1 -5\n");
        Assert.Equal([(0, 1, 2), (4, 3, 2), (0, 4, 0)], Triangles(file));
    }

    [Fact]
    public void EverySlashFormUsesTheVertexIndexOnly()
    {
        var file = Parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvn 0 0 1\nf 1 2 3\nf 1/1 2/1 3/1\nf 1//1 2//1 3//1\nf 1/1/1 2/1/1 3/1/1\nf 2/1 4//1 3/1/1\n");
        Assert.Equal([(0, 1, 2), (0, 1, 2), (0, 1, 2), (0, 1, 2), (1, 3, 2)], Triangles(file));
    }

    [Fact]
    public void CommentsBlankLinesTabsAndExtraVertexNumbersAreReadPast()
    {
        var file = Parse("# a comment\n\n   \nv 0 0 0 1.0\r\nv\t1\t0\t0 # inline comment\nv 0 2.5e-1 -0 0.5 0.5 0.5\nf 1 2 3 # last\n");
        Assert.Equal([new Vec3(0, 0, 0), new Vec3(1, 0, 0), new Vec3(0, 0.25, 0)], file.Mesh.Vertices);
        Assert.Single(file.Mesh.Triangles);
        Assert.Empty(file.Warnings);
    }

    /// <summary>Every line that is not v or f, known keyword or not, adds to one warning that counts them by keyword.</summary>
    [Fact]
    public void IgnoredLinesGiveOneWarning()
    {
        var file = Parse("mtllib a.mtl\no thing\ng group\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn 0 0 1\nvt 0 0\ns off\nusemtl red\ncurv 0 1 2\nf 1 2 3\n");
        Assert.Single(file.Mesh.Triangles);
        var warning = Assert.Single(file.Warnings);
        Assert.Equal("test.obj: ignored 9 lines the mesh reader does not use (curv ×1, g ×1, mtllib ×1, o ×1, s ×1, usemtl ×1, vn ×2, vt ×1; the first at line 1): only v and f lines are read", warning);
    }

    [Fact]
    public void BoundsLeaveOutUnusedVertices()
    {
        var mesh = Parse("v -1 2 3\nv 9 9 9\nv 4 -5 6\nv 0 0 -7\nf 1 3 4\n").Mesh;
        Assert.Equal(4, mesh.Vertices.Count);
        Assert.Equal((new Vec3(-1, -5, -7), new Vec3(4, 2, 6)), mesh.Bounds);
    }

    /// <summary>The error is raised where the line is, with the words a user sees.</summary>
    [Fact]
    public void AnErrorNamesFileLineAndProblem()
    {
        var error = Assert.Throws<MeshError>(() => Parse("v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 9\n"));
        Assert.Equal("test.obj: line 5: face index 9 is out of range: 3 vertices are defined above this line", error.Message);
    }

    [Theory]
    [InlineData("NaN")]
    [InlineData("-nan")]
    [InlineData("inf")]
    [InlineData("Infinity")]
    [InlineData("-1e400")]
    public void NonFiniteSpellingsAreNamedAsSuch(string coordinate)
    {
        var error = Assert.Throws<MeshError>(() => Parse($"v 0 {coordinate} 0\n"));
        Assert.Equal($"test.obj: line 1: coordinate '{coordinate}' is not finite; every coordinate must be a finite number", error.Message);
    }
}
