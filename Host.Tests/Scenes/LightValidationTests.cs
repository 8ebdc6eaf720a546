using System.Text.Json.Nodes;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Tests.Scenes;

/// <summary>Area and directional lights in scene files: what loads, and one test per problem the loader must name.</summary>
public class LightValidationTests
{
    // The area light lies off the grid on purpose: it is an emitter, not a primitive.
    private const string Valid = """
        {
          "image": { "width": 8, "height": 8 },
          "grid": { "integerBits": 4 },
          "camera": { "position": [4, 4, -3], "lookAt": [4, 4, 8] },
          "materials": { "white": { "diffuse": [0.8, 0.8, 0.8] } },
          "areaLights": [ { "min": [2.25, 7.5, 3], "max": [5.75, 7.5, 6.1], "radiance": [4, 5, 6] } ],
          "directionalLights": [ { "direction": [0, -3, 4], "irradiance": [1, 2, 0] } ],
          "rectangles": [ { "min": [0, 0, 8], "max": [8, 8, 8], "material": "white" } ]
        }
        """;

    private static SceneError Reject(Action<JsonObject> edit) => SceneRejection.Reject(Valid, edit);

    private static void AssertError(SceneError error, string element, string problemPart) =>
        SceneRejection.AssertError(error, element, problemPart);

    private static JsonNode Area(JsonObject s) => s["areaLights"]![0]!;

    private static JsonNode Directional(JsonObject s) => s["directionalLights"]![0]!;

    [Fact]
    public void AreaAndDirectionalLightsLoad()
    {
        var scene = SceneLoader.Parse(Valid, "ok.json");
        var area = Assert.Single(scene.AreaLights);
        Assert.Equal(1, area.FlatAxis);
        Assert.Equal((0, 2), area.PlaneAxes);
        Assert.Equal(3.5 * 3.1, area.Area, 12);
        Assert.Equal(new Vec3(4, 5, 6), area.Radiance);
        var directional = Assert.Single(scene.DirectionalLights);
        // [0, -3, 4] has length 5.
        Assert.Equal(0, directional.Direction.X);
        Assert.Equal(-0.6, directional.Direction.Y, 14);
        Assert.Equal(0.8, directional.Direction.Z, 14);
        Assert.Equal(new Vec3(1, 2, 0), directional.Irradiance);
        Assert.Empty(scene.Lights);
    }

    [Fact]
    public void ScenesWithoutTheNewListsHaveNone()
    {
        var scene = SceneLoader.Load(Path.Combine(RepositoryPaths.Scenes, "qornell-64.json"));
        Assert.Empty(scene.AreaLights);
        Assert.Empty(scene.DirectionalLights);
        Assert.Equal(2, scene.Lights.Count);
    }

    [Theory]
    [InlineData(1e-300)]
    [InlineData(1e300)]
    public void DirectionOfAnyFiniteLengthIsNormalised(double scale)
    {
        var scene = SceneLoader.Parse(Valid.Replace("[0, -3, 4]", $"[0, {-3 * scale:R}, {4 * scale:R}]"), "ok.json");
        var direction = scene.DirectionalLights[0].Direction;
        Assert.Equal(-0.6, direction.Y, 12);
        Assert.Equal(0.8, direction.Z, 12);
    }

    [Fact]
    public void AreaLightNaN()
    {
        var error = Assert.Throws<SceneError>(() => SceneLoader.Parse(Valid.Replace("[4, 5, 6]", "[4, \"NaN\", 6]"), "bad.json"));
        Assert.Equal("areaLights[0].radiance[1]", error.Element);
        Assert.Contains("NaN", error.Problem);
    }

    [Fact]
    public void DirectionalLightOverflowingNumber()
    {
        var error = Assert.Throws<SceneError>(() => SceneLoader.Parse(Valid.Replace("[0, -3, 4]", "[0, -1e999, 4]"), "bad.json"));
        Assert.StartsWith("directionalLights[0].direction", error.Element);
    }

    [Fact]
    public void AreaLightFlatOnNoAxis() =>
        AssertError(Reject(s => Area(s)["max"]![1] = 8), "areaLights[0]", "is not a rectangle: min and max differ on every axis");

    [Fact]
    public void AreaLightFlatOnTwoAxes() =>
        AssertError(Reject(s => Area(s)["max"]![2] = 3), "areaLights[0]", "is not a rectangle: min equals max on 2 axes");

    [Fact]
    public void AreaLightMinAboveMax() =>
        AssertError(Reject(s => Area(s)["min"]![0] = 6), "areaLights[0].min[0]", "6 is greater than max[0] = 5.75");

    [Fact]
    public void AreaLightNegativeRadiance() =>
        AssertError(Reject(s => Area(s)["radiance"]![2] = -0.5), "areaLights[0].radiance[2]", "-0.5 is negative");

    [Fact]
    public void AreaLightUnknownField()
    {
        var error = Reject(s => Area(s)["intensity"] = new JsonArray(1, 1, 1));
        Assert.StartsWith("areaLights[0]", error.Element);
        Assert.Contains("unknown field 'intensity'", error.Problem);
    }

    [Fact]
    public void AreaLightMissingRadiance() =>
        AssertError(Reject(s => Area(s).AsObject().Remove("radiance")), "areaLights[0].radiance", "missing");

    [Fact]
    public void AreaLightCornerWithTwoNumbers() =>
        AssertError(Reject(s => Area(s)["min"] = new JsonArray(1, 2)), "areaLights[0].min", "expected 3");

    [Fact]
    public void DirectionalLightZeroDirection() =>
        AssertError(Reject(s => Directional(s)["direction"] = new JsonArray(0, 0, 0)), "directionalLights[0].direction", "is zero");

    [Fact]
    public void DirectionalLightNegativeIrradiance() =>
        AssertError(Reject(s => Directional(s)["irradiance"]![0] = -1), "directionalLights[0].irradiance[0]", "-1 is negative");

    [Fact]
    public void DirectionalLightUnknownField()
    {
        var error = Reject(s => Directional(s)["position"] = new JsonArray(1, 1, 1));
        Assert.StartsWith("directionalLights[0]", error.Element);
        Assert.Contains("unknown field 'position'", error.Problem);
    }

    [Fact]
    public void DirectionalLightMissingIrradiance() =>
        AssertError(Reject(s => Directional(s).AsObject().Remove("irradiance")), "directionalLights[0].irradiance", "missing");

    [Fact]
    public void NullLightEntry() =>
        AssertError(Reject(s => s["areaLights"]!.AsArray().Add(null)), "areaLights[1]", "is null");
}
