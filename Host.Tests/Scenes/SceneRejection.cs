using System.Text.Json.Nodes;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Tests.Scenes;

/// <summary>Validation cases written as one edit of a valid scene, and the one-line error each must give.</summary>
internal static class SceneRejection
{
    /// <summary>The error of <paramref name="valid"/> after <paramref name="edit"/>, parsed as "bad.json".</summary>
    public static SceneError Reject(string valid, Action<JsonObject> edit)
    {
        var scene = JsonNode.Parse(valid)!.AsObject();
        edit(scene);
        return Assert.Throws<SceneError>(() => SceneLoader.Parse(scene.ToJsonString(), "bad.json"));
    }

    public static void AssertError(SceneError error, string element, string problemPart)
    {
        Assert.Equal("bad.json", error.File);
        Assert.Equal(element, error.Element);
        Assert.Contains(problemPart, error.Problem);
        Assert.DoesNotContain('\n', error.Message);
        Assert.StartsWith($"bad.json: {element}: ", error.Message);
    }
}
