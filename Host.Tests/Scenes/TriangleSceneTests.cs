using System.Globalization;
using System.Text;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Tests.BadInput;

namespace QuantumRayTracing.Tests.Scenes;

/// <summary>
/// Scene files with triangles and meshes: ids after the rectangles, mesh files read relative to the scene file and
/// placed by their transform, the grid chosen from the scene or taken from the file with every vertex rounded onto
/// it, and bad input refused in one line naming the scene, the element and, for a mesh, its file and line.
/// </summary>
[Collection(BadInputCollection.Name)]
public sealed class TriangleSceneTests : IDisposable
{
    private readonly ScratchDirectory _dir = new("qrt-triangle-scene-");

    public void Dispose() => _dir.Dispose();

    // A unit square in z = 0 as two triangles, and a third triangle beside it (the smallest edge 0.5).
    private const string Square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2.5 0 0\nv 2 0.5 0\nf 1 2 3 4\nf 5 6 7\n";

    private string Scene(string fields, string name = "scene.json")
    {
        var path = _dir.File(name);
        File.WriteAllText(path, $$"""
            {
              "image": { "width": 8, "height": 8 },
              "camera": { "position": [4, 4, -6], "lookAt": [4, 4, 8] },
              "materials": { "white": { "diffuse": [0.5, 0.5, 0.5] } },
              {{fields}}
            }
            """);
        return path;
    }

    private string Obj(string name, string text)
    {
        var path = _dir.File(name);
        Directory.CreateDirectory(Path.GetDirectoryName(path)!);
        File.WriteAllText(path, text);
        return path;
    }

    [Fact]
    public void TrianglesAndAMeshFollowTheRectanglesOnAGridChosenFromTheScene()
    {
        Obj("models/square.obj", Square);
        var scene = SceneLoader.Load(Scene("""
            "rectangles": [ { "min": [0, 0, 12], "max": [8, 8, 12], "material": "white" } ],
            "triangles": [ { "a": [1, 1, 10], "b": [3, 1, 10], "c": [1, 3.25, 10], "material": "white" } ],
            "meshes": [ { "file": "models/square.obj", "material": "white", "translate": [2, 3, 8], "scale": 2, "rotate": [0, 0, 90] } ]
            """));
        Assert.Equal([0, 1, 2, 3, 4], scene.Primitives.Select(p => p.Id));
        Assert.IsType<Rectangle>(scene.Primitives[0]);
        Assert.All(scene.Primitives.Skip(1), p => Assert.IsType<Triangle>(p));
        // Reach 12 needs 4 integer bits; the smallest edge, 0.5 · 2 = 1 (the mesh's) beside 2 and 2.25, spans 4 steps at 2 fraction bits.
        Assert.Equal(new CoordinateGrid(4, 2), scene.Grid);
        Assert.True(scene.Quantisation!.GridChosen);
        // +90° about z takes x to y: the scaled corner (2, 0, 0) lands at (2, 3, 8) + (0, 2, 0).
        var mesh = scene.Primitives.Skip(2).Cast<Triangle>().ToArray();
        Assert.Equal(new Vec3(2, 5, 8), mesh[0].B);
        Assert.Equal(0, scene.Quantisation.LargestDisplacement);
        Assert.Contains("grid chosen from the scene's extent", SceneCheck.Summary(scene));
    }

    [Fact]
    public void AGivenGridRoundsEveryVertexOntoItAndReportsHowFar()
    {
        Obj("square.obj", Square);
        var scene = SceneLoader.Load(Scene("""
            "grid": { "integerBits": 4, "fractionBits": 1 },
            "triangles": [ { "a": [1, 1, 10], "b": [3.2, 1, 10], "c": [1, 3, 10], "material": "white" } ],
            "meshes": [ { "file": "square.obj", "material": "white", "translate": [4, 4, 8] } ]
            """));
        Assert.Equal(new CoordinateGrid(4, 1), scene.Grid);
        Assert.False(scene.Quantisation!.GridChosen);
        Assert.Equal(new Vec3(3, 1, 10), ((Triangle)scene.Primitives[0]).B);
        Assert.Equal(0.2, scene.Quantisation.LargestDisplacement, 12);
        Assert.Contains("largest vertex displacement 0.2 (0.4 steps)", SceneCheck.Summary(scene));
    }

    /// <summary>A scene of rectangles and triangles as a cluster worker receives it (JSON) comes back the same, each primitive of its kind.</summary>
    [Fact]
    public void RectanglesAndTrianglesGoToAWorkerAndBack()
    {
        Obj("square.obj", Square);
        var scene = SceneLoader.Load(Scene("""
            "rectangles": [ { "min": [0, 0, 12], "max": [8, 8, 12], "material": "white" } ],
            "meshes": [ { "file": "square.obj", "material": "white", "translate": [2, 3, 8] } ]
            """));
        var back = System.Text.Json.JsonSerializer.Deserialize<Scene>(QuantumRayTracing.Rendering.PartRequest.SceneText(scene))!;
        Assert.Equal(scene.Primitives, back.Primitives);
        Assert.Equal(scene.Quantisation!.LargestDisplacement, back.Quantisation!.LargestDisplacement);
    }

    /// <summary>Element → phrase: each scene is one defect away from a valid one.</summary>
    public static TheoryData<string, string, string, string?> BadCases => new()
    {
        { """ "meshes": [ { "file": "missing.obj", "material": "white" } ] """, "meshes[0]", "missing.obj: file: not found", null },
        { """ "meshes": [ { "file": "range.obj", "material": "white" } ] """, "meshes[0]", "range.obj: line 4: face index 9 is out of range", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n" },
        { """ "meshes": [ { "file": "nan.obj", "material": "white" } ] """, "meshes[0]", "nan.obj: line 2: coordinate 'nan' is not finite", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n" },
        { """ "meshes": [ { "file": "none.obj", "material": "white" } ] """, "meshes[0]", "no triangles", "v 0 0 0\nv 1 0 0\nv 0 1 0\n" },
        { """ "meshes": [ { "file": "flat.obj", "material": "white" } ] """, "meshes[0]", "the only triangle has zero area", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n" },
        { """ "grid": { "integerBits": 4 }, "meshes": [ { "file": "tiny.obj", "material": "white", "translate": [4, 4, 8] } ] """, "meshes[0]", "all 2 triangles collapse on the 4-bit integer grid",
            "v 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nv 0.1 0.1 0\nf 1 2 3\nf 2 4 3\n" },
        { """ "meshes": [ { "file": "square.obj", "material": "white", "translate": [-3, 0, 0] } ] """, "meshes[0]", "lies outside the grid", Square },
        { """ "meshes": [ { "file": "square.obj", "material": "white", "scale": 0 } ] """, "meshes[0].scale", "0 is outside", Square },
        { """ "meshes": [ { "file": "square.obj" } ] """, "meshes[0].material", "missing", Square },
        { """ "meshes": [ { "material": "white" } ] """, "meshes[0].file", "missing", null },
        { """ "triangles": [ { "a": [1, 1, 1], "b": [2, 2, 2], "c": [3, 3, 3], "material": "white" } ] """, "triangles[0]", "has no area", null },
        { """ "grid": { "integerBits": 4 }, "triangles": [ { "a": [1, 1, 1], "b": [1.2, 1, 1], "c": [1, 1.2, 1], "material": "white" } ] """, "triangles[0]", "collapses to a line or a point", null },
        { """ "grid": { "integerBits": 4 }, "triangles": [ { "a": [1, 1, 1], "b": [17, 1, 1], "c": [1, 3, 1], "material": "white" } ] """, "triangles[0].b", "lies outside the grid 0..15", null },
        { """ "triangles": [ { "a": [1, 1, 1], "b": [3, 1, 1], "material": "white" } ] """, "triangles[0].c", "missing", null },
        { """ "triangles": [ { "a": [1, 1, 1], "b": [3, 1, 1], "c": [1, 3, 1], "material": "gold" } ] """, "triangles[0].material", "'gold' is not defined", null },
        { """ "triangles": [ { "a": [1, 1, 1], "b": [3, 1, 1], "c": [1, 3, 1], "material": "white", "normal": [0, 0, 1] } ] """, "triangles[0].normal", "unknown field 'normal'", null },
        { """ "triangles": [ { "a": [3, 4, -6], "b": [6, 4, -6], "c": [3, 7, -6], "material": "white" } ], "grid": { "integerBits": 4 } """, "triangles[0].a", "outside the grid", null },
    };

    [Theory]
    [MemberData(nameof(BadCases))]
    public void BadTrianglesAndMeshesAreRefusedInOneLine(string fields, string element, string problem, string? obj)
    {
        if (obj is not null) Obj(System.Text.RegularExpressions.Regex.Match(fields, "\"file\": \"([^\"]+)\"").Groups[1].Value, obj);
        var scene = Scene(fields);
        var refused = Assert.Throws<SceneError>(() => SceneLoader.Load(scene));
        Assert.Equal(element, refused.Element);
        Assert.Contains(problem, refused.Problem);
        Assert.DoesNotContain('\n', refused.Message);
        Assert.StartsWith($"{scene}: {element}: ", refused.Message);
    }

    /// <summary>A camera standing on a triangle (in its plane, inside it) is refused, as on a rectangle.</summary>
    [Fact]
    public void ACameraOnATriangleIsRefused()
    {
        var path = Scene(""" "triangles": [ { "a": [1, 1, 1], "b": [9, 1, 1], "c": [1, 9, 1], "material": "white" } ] """);
        File.WriteAllText(path, File.ReadAllText(path).Replace("[4, 4, -6]", "[2, 2, 1]"));
        var error = Assert.Throws<SceneError>(() => SceneLoader.Load(path));
        Assert.Equal("camera.position", error.Element);
        Assert.Contains("lies on triangle 0", error.Problem);
    }

    /// <summary>Two meshes of 32,769 triangles each: 65,538 primitives, two past the 16-qubit index register.</summary>
    [Fact]
    public void MoreThan65536PrimitivesAreRefused()
    {
        var text = new StringBuilder();
        for (var k = 0; k < 32_769; k++) text.Append(CultureInfo.InvariantCulture, $"v {k % 100} {k / 100} 0\nv {k % 100 + 1} {k / 100} 0\nv {k % 100} {k / 100 + 1} 0\nf -3 -2 -1\n");
        Obj("half.obj", text.ToString());
        var scene = Scene("""
            "meshes": [ { "file": "half.obj", "material": "white" }, { "file": "half.obj", "material": "white", "translate": [0, 0, 1] } ]
            """);
        var error = Assert.Throws<SceneError>(() => SceneLoader.Load(scene));
        Assert.Equal("meshes", error.Element);
        Assert.Contains("65538 primitives; at most 65536", error.Problem);
    }

    /// <summary>`estimate` and `export search` price and write the gate-level oracle, which takes rectangles only: a scene with triangles is refused in one line.</summary>
    [Fact]
    public void TheGateLevelOracleCommandsRefuseTriangles()
    {
        var scene = Scene(""" "triangles": [ { "a": [1, 1, 9], "b": [9, 1, 9], "c": [1, 9, 9], "material": "white" }, { "a": [1, 1, 10], "b": [9, 1, 10], "c": [1, 9, 10], "material": "white" } ] """);
        Outcome.Of("estimate", scene, "--frame").AssertBadInput("scene scene", "takes rectangles only");
        Outcome.Of("estimate", scene).AssertBadInput("scene scene", "takes rectangles only");
        Outcome.Of("export", "search", scene, "--pixel", "0,0", "-o", _dir.File("out.qasm")).AssertBadInput("scene scene", "takes rectangles only");
        Assert.False(File.Exists(_dir.File("out.qasm")));
    }

    /// <summary>`render` on a scene whose mesh file is missing: exit code 2, one line naming the scene, the element and the mesh file, no image.</summary>
    [Fact]
    public void RenderRefusesAMissingMeshWithoutWritingAnImage()
    {
        var scene = Scene(""" "meshes": [ { "file": "gone.obj", "material": "white" } ] """);
        var output = Path.Combine(_dir.Path, "out");
        Directory.CreateDirectory(output);
        Outcome.Of("render", scene, "--engine", "analytic", "-o", Path.Combine(output, "image.png"))
            .AssertBadInput(scene, "meshes[0]", "gone.obj: file: not found", output);
    }
}
