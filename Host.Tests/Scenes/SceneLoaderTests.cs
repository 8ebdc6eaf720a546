using System.Text.Json.Nodes;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Tests.Scenes;

public class SceneLoaderTests
{
    private const string Valid = """
        {
          "image": { "width": 16, "height": 8 },
          "grid": { "integerBits": 4, "fractionBits": 1 },
          "camera": { "position": [4, 4, -3.3], "lookAt": [4, 4, 8], "verticalFov": 50 },
          "materials": { "white": { "diffuse": [0.8, 0.8, 0.8] }, "glass": { "diffuse": [0, 0, 0], "mirror": 1 } },
          "lights": [ { "position": [4, 7, 4], "intensity": [10, 10, 10] } ],
          "rectangles": [
            { "min": [0, 0, 8], "max": [8, 8, 8], "material": "white" },
            { "min": [1.5, 0, 2], "max": [1.5, 3, 6.5], "material": "glass" }
          ]
        }
        """;

    private static SceneError Reject(Action<JsonObject> edit) => SceneRejection.Reject(Valid, edit);

    private static void AssertError(SceneError error, string element, string problemPart) =>
        SceneRejection.AssertError(error, element, problemPart);

    [Fact]
    public void ValidSceneLoads()
    {
        var scene = SceneLoader.Parse(Valid, "ok.json");
        Assert.Equal((16, 8), (scene.Width, scene.Height));
        Assert.Equal(new CoordinateGrid(4, 1), scene.Grid);
        Assert.Equal(2, scene.Rectangles().Count);
        Assert.Equal(2, scene.Rectangles()[0].FlatAxis);
        Assert.Equal(0, scene.Rectangles()[1].FlatAxis);
        Assert.True(scene.Rectangles()[1].Material.IsMirror);
        Assert.Equal(1, scene.Rectangles()[1].Id);
    }

    [Fact]
    public void EveryShippedSceneLoads()
    {
        var files = Directory.GetFiles(RepositoryPaths.Scenes, "*.json");
        Assert.NotEmpty(files);
        foreach (var file in files) Assert.NotEmpty(SceneLoader.Load(file).Rectangles());
    }

    [Fact]
    public void NegativeCoordinate() =>
        AssertError(Reject(s => s["rectangles"]![0]!["min"]![0] = -1), "rectangles[0].min[0]", "-1 is outside the grid 0..15.5");

    [Fact]
    public void CoordinateBeyondTheGrid() =>
        AssertError(Reject(s => s["rectangles"]![0]!["max"]![1] = 16), "rectangles[0].max[1]", "16 is outside the grid");

    [Fact]
    public void CoordinateBetweenGridValues() =>
        AssertError(Reject(s => s["rectangles"]![0]!["max"]![1] = 7.25), "rectangles[0].max[1]", "7.25 is not on the grid");

    [Fact]
    public void RectangleWithNoFlatAxis() =>
        AssertError(Reject(s => s["rectangles"]![0]!["max"]![2] = 9), "rectangles[0]", "not axis-aligned");

    [Fact]
    public void RectangleWithTwoFlatAxes() =>
        AssertError(Reject(s => s["rectangles"]![0]!["max"]![0] = 0), "rectangles[0]", "min equals max on 2 axes");

    [Fact]
    public void MinAboveMax() =>
        AssertError(Reject(s => s["rectangles"]![0]!["min"]![0] = 9), "rectangles[0].min[0]", "greater than max[0]");

    [Fact]
    public void ZeroPrimitives() =>
        AssertError(Reject(s => s["rectangles"] = new JsonArray()), "rectangles", "no primitives");

    [Fact]
    public void UnknownFieldAtTopLevel() =>
        AssertError(Reject(s => s["colour"] = "red"), "colour", "unknown field 'colour'");

    [Fact]
    public void UnknownFieldInARectangle()
    {
        var error = Reject(s => s["rectangles"]![1]!["colour"] = "red");
        Assert.Contains("unknown field 'colour'", error.Problem);
        Assert.StartsWith("rectangles[1]", error.Element);
    }

    [Fact]
    public void NaNIsRejected()
    {
        var error = Assert.Throws<SceneError>(() => SceneLoader.Parse(Valid.Replace("\"verticalFov\": 50", "\"verticalFov\": \"NaN\""), "bad.json"));
        Assert.Equal("camera.verticalFov", error.Element);
        Assert.Contains("NaN", error.Problem);
    }

    [Fact]
    public void OverflowingNumberIsRejected()
    {
        var error = Assert.Throws<SceneError>(() => SceneLoader.Parse(Valid.Replace("[4, 7, 4]", "[4, 1e999, 4]"), "bad.json"));
        Assert.StartsWith("lights[0].position", error.Element);
    }

    [Fact]
    public void UndefinedMaterial() =>
        AssertError(Reject(s => s["rectangles"]![0]!["material"] = "gold"), "rectangles[0].material", "'gold' is not defined");

    [Fact]
    public void MissingCamera() =>
        AssertError(Reject(s => s.Remove("camera")), "camera", "missing");

    [Fact]
    public void VectorWithTwoNumbers() =>
        AssertError(Reject(s => s["camera"]!["position"] = new JsonArray(1, 2)), "camera.position", "expected 3");

    [Fact]
    public void CameraLookingAtItself() =>
        AssertError(Reject(s => s["camera"]!["lookAt"] = new JsonArray(4, 4, -3.3)), "camera.lookAt", "no view direction");

    // Rectangles are flat: a camera inside one is a camera in its plane and within its bounds, edges included.
    [Theory]
    [InlineData(4, 4, 8)]     // inside rectangle 0 (z = 8, x and y 0..8)
    [InlineData(8, 0, 8)]     // its corner
    [InlineData(1.5, 3, 2)]   // a corner of rectangle 1 (x = 1.5)
    public void CameraOnARectangle(double x, double y, double z)
    {
        var error = Reject(s =>
        {
            s["camera"]!["position"] = new JsonArray(x, y, z);
            s["camera"]!["lookAt"] = new JsonArray(x + 1, y, z + 1);
        });
        AssertError(error, "camera.position", $"lies on rectangles[{(x == 1.5 ? 1 : 0)}]");
    }

    [Theory]
    [InlineData(9, 4, 8)]       // in rectangle 0's plane, beside it
    [InlineData(4, 4, 7.999)]   // just in front of it
    [InlineData(1.5, 3.01, 4)]  // in rectangle 1's plane, just above it
    public void CameraNearARectangleIsFine(double x, double y, double z)
    {
        var scene = JsonNode.Parse(Valid)!.AsObject();
        scene["camera"]!["position"] = new JsonArray(x, y, z);
        scene["camera"]!["lookAt"] = new JsonArray(x + 1, y, z + 1);
        Assert.Equal(new Vec3(x, y, z), SceneLoader.Parse(scene.ToJsonString(), "ok.json").Camera.Position);
    }

    [Fact]
    public void DuplicateField()
    {
        var text = Valid.Replace("\"width\": 16,", "\"width\": 16, \"width\": 9,");
        Assert.NotEqual(Valid, text);
        var error = Assert.Throws<SceneError>(() => SceneLoader.Parse(text, "bad.json"));
        Assert.Equal("image.width", error.Element);
        Assert.Contains("appears twice", error.Problem);
    }

    [Fact]
    public void ImageSizeZero() =>
        AssertError(Reject(s => s["image"]!["width"] = 0), "image.width", "0 is outside 1..8192");

    [Fact]
    public void DiffuseAboveOne() =>
        AssertError(Reject(s => s["materials"]!["white"]!["diffuse"]![2] = 1.5), "materials.white.diffuse[2]", "outside [0, 1]");

    [Fact]
    public void MalformedJson()
    {
        var error = Assert.Throws<SceneError>(() => SceneLoader.Parse("{ \"image\": ", "bad.json"));
        Assert.Contains("not valid JSON", error.Problem);
    }

    [Fact]
    public void MissingFile()
    {
        var path = Path.Combine(Path.GetTempPath(), "qrt-no-such-scene.json");
        var error = Assert.Throws<SceneError>(() => SceneLoader.Load(path));
        Assert.Equal(path, error.File);
        Assert.Contains("not found", error.Problem);
    }
}
