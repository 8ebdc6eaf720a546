using System.Text;
using QuantumRayTracing.Scenes.Meshes;
using QuantumRayTracing.Tests.BadInput;

namespace QuantumRayTracing.Tests.Scenes.Meshes;

/// <summary>
/// Mesh files `qrt scenes check` must refuse with one line naming the file, the line (or element) and the problem,
/// and exit code 2: the corpus in BadInput/Scenes/Meshes (the first line of each says what is wrong), and cases
/// written at test time (too many triangles, missing file, a directory).
/// </summary>
[Collection(BadInputCollection.Name)]
public sealed class BadMeshFileTests : IDisposable
{
    private readonly ScratchDirectory _input = new("qrt-bad-mesh-");

    public void Dispose() => _input.Dispose();

    private static string Mesh(string name) => Path.Combine(Corpus.Root, "Scenes", "Meshes", name);

    /// <summary>File → element → phrase of the problem.</summary>
    public static TheoryData<string, string, string> Cases => new()
    {
        { "index-out-of-range.obj", "line 5", "face index 4 is out of range: 3 vertices" },
        { "index-zero.obj", "line 5", "face index 0: OBJ indices start at 1" },
        { "negative-index-out-of-range.obj", "line 5", "face index -4 is out of range: 3 vertices" },
        { "forward-index.obj", "line 4", "face index 3 is out of range: 2 vertices are defined above this line" },
        { "malformed-number.obj", "line 3", "'1.5.2' is not a number" },
        { "malformed-index.obj", "line 5", "face corner 'three': 'three' is not a vertex index" },
        { "nan-coordinate.obj", "line 4", "coordinate 'nan' is not finite" },
        { "infinite-coordinate.obj", "line 3", "coordinate '1e999' is not finite" },
        { "vertex-two-coordinates.obj", "line 3", "a vertex needs three coordinates 'v x y z'; found 2" },
        { "face-two-vertices.obj", "line 5", "a face needs at least 3 vertices; this one has 2" },
        { "no-triangles.obj", "line 4", "no triangles" },
        { "empty.obj", "line 1", "no triangles" },
        { "zero-area.obj", "triangles", "the only triangle has zero area" },
        { "too-large.obj", "bounds", "the mesh spans 100000 units; a 16-bit grid reaches 65535" },
        { "collapses-on-grid.obj", "grid", "the only triangle collapses on the 10.6 fixed-point grid" },
    };

    [Theory]
    [MemberData(nameof(Cases))]
    public void ScenesCheckRefuses(string file, string element, string problem) =>
        Outcome.Of("scenes", "check", Mesh(file)).AssertBadInput(Mesh(file), element, problem, null);

    [Fact]
    public void EveryCorpusFileIsACase() =>
        Assert.Equal(Directory.GetFiles(Path.Combine(Corpus.Root, "Scenes", "Meshes")).Select(Path.GetFileName).Order(), Cases.Select(c => (string)c[0]).Order());

    /// <summary>65,537 faces: one past the 16-qubit index register; the error names the face line that passes the limit.</summary>
    [Fact]
    public void TooManyTriangles()
    {
        var text = new StringBuilder("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
        for (var k = 0; k <= TriangleMesh.MaxTriangles; k++) text.Append("f 1 2 3\n");
        var file = _input.File("too-many.obj");
        File.WriteAllText(file, text.ToString());
        // Lines 1-3 are vertices; face k (from 0) is on line 4 + k, so face 65,536 is on line 65,540.
        Outcome.Of("scenes", "check", file).AssertBadInput(file, "line 65540", "more than 65536 triangles", null);
    }

    /// <summary>The same limit through the fan: one polygon of 65,539 corners makes 65,537 triangles.</summary>
    [Fact]
    public void TooManyTrianglesInOneFace()
    {
        var text = new StringBuilder();
        for (var k = 0; k < 4; k++) text.Append($"v {k} {k * k} 0\n");
        text.Append('f');
        for (var k = 0; k < TriangleMesh.MaxTriangles + 3; k++) text.Append(' ').Append(1 + k % 4);
        var file = _input.File("huge-polygon.obj");
        File.WriteAllText(file, text.Append('\n').ToString());
        Outcome.Of("scenes", "check", file).AssertBadInput(file, "line 5", "more than 65536 triangles", null);
    }

    [Fact]
    public void MissingFile()
    {
        foreach (var name in new[] { "no-such-mesh.obj", "no-such-mesh.gltf", "no-such-mesh.glb" })
            Outcome.Of("scenes", "check", _input.File(name)).AssertBadInput(_input.File(name), "file", "not found", null);
    }

    [Fact]
    public void DirectoryInsteadOfAFile()
    {
        var directory = _input.File("model.obj");
        Directory.CreateDirectory(directory);
        Outcome.Of("scenes", "check", directory).AssertBadInput(directory, "file", "is a directory", null);
    }

    /// <summary>/proc/self/mem opens but its read fails for root too (BadSceneInputTests says why); linked under a mesh's name.</summary>
    [LinuxFact("/proc/self/mem, whose read fails for root too")]
    public void FileWhoseReadFails()
    {
        var link = _input.File("unreadable.obj");
        File.CreateSymbolicLink(link, "/proc/self/mem");
        Outcome.Of("scenes", "check", link).AssertBadInput(link, "file", "cannot be read", null);
    }

    /// <summary>A glTF file that is not one: SharpGLTF's refusal, in one line.</summary>
    [Fact]
    public void GltfThatIsNotJson()
    {
        var file = _input.File("broken.gltf");
        File.WriteAllText(file, "{ this is not json");
        Outcome.Of("scenes", "check", file).AssertBadInput(file, "file", "is not a glTF 2.0 file that can be read", null);
    }

    [Fact]
    public void UnknownExtensionIsRefusedByTheReader()
    {
        var error = Assert.Throws<MeshError>(() => MeshReader.Read("model.stl"));
        Assert.Equal("model.stl: file: the extension '.stl' is not a mesh format: mesh files are read by extension, one of .obj, .gltf, .glb", error.Message);
    }
}
