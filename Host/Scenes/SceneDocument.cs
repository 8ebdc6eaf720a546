using System.Text.Json.Serialization;

namespace QuantumRayTracing.Scenes;

/// <summary>
/// The scene file as written (docs/scenes.md): plain JSON, camelCase names, unknown fields rejected.
/// Every member is nullable so that the loader, not the serializer, words the error for a missing one.
/// </summary>
[JsonUnmappedMemberHandling(JsonUnmappedMemberHandling.Disallow)]
public sealed class SceneDocument
{
    public string? Name { get; set; }
    public ImageDocument? Image { get; set; }
    public GridDocument? Grid { get; set; }
    public CameraDocument? Camera { get; set; }
    public double? Ambient { get; set; }
    public Dictionary<string, MaterialDocument>? Materials { get; set; }
    public List<LightDocument>? Lights { get; set; }
    public List<AreaLightDocument>? AreaLights { get; set; }
    public List<DirectionalLightDocument>? DirectionalLights { get; set; }
    public List<RectangleDocument>? Rectangles { get; set; }
    public List<TriangleDocument>? Triangles { get; set; }
    public List<MeshDocument>? Meshes { get; set; }

    [JsonUnmappedMemberHandling(JsonUnmappedMemberHandling.Disallow)]
    public sealed class ImageDocument
    {
        public int? Width { get; set; }
        public int? Height { get; set; }
    }

    [JsonUnmappedMemberHandling(JsonUnmappedMemberHandling.Disallow)]
    public sealed class GridDocument
    {
        public int? IntegerBits { get; set; }
        public int? FractionBits { get; set; }
    }

    [JsonUnmappedMemberHandling(JsonUnmappedMemberHandling.Disallow)]
    public sealed class CameraDocument
    {
        public double[]? Position { get; set; }
        public double[]? LookAt { get; set; }
        public double[]? Up { get; set; }
        public double? VerticalFov { get; set; }
    }

    [JsonUnmappedMemberHandling(JsonUnmappedMemberHandling.Disallow)]
    public sealed class MaterialDocument
    {
        public double[]? Diffuse { get; set; }
        public double? Mirror { get; set; }
    }

    [JsonUnmappedMemberHandling(JsonUnmappedMemberHandling.Disallow)]
    public sealed class LightDocument
    {
        public double[]? Position { get; set; }
        public double[]? Intensity { get; set; }
    }

    [JsonUnmappedMemberHandling(JsonUnmappedMemberHandling.Disallow)]
    public sealed class AreaLightDocument
    {
        public double[]? Min { get; set; }
        public double[]? Max { get; set; }
        public double[]? Radiance { get; set; }
    }

    [JsonUnmappedMemberHandling(JsonUnmappedMemberHandling.Disallow)]
    public sealed class DirectionalLightDocument
    {
        public double[]? Direction { get; set; }
        public double[]? Irradiance { get; set; }
    }

    [JsonUnmappedMemberHandling(JsonUnmappedMemberHandling.Disallow)]
    public sealed class RectangleDocument
    {
        public double[]? Min { get; set; }
        public double[]? Max { get; set; }
        public string? Material { get; set; }
    }

    [JsonUnmappedMemberHandling(JsonUnmappedMemberHandling.Disallow)]
    public sealed class TriangleDocument
    {
        public double[]? A { get; set; }
        public double[]? B { get; set; }
        public double[]? C { get; set; }
        public string? Material { get; set; }
    }

    [JsonUnmappedMemberHandling(JsonUnmappedMemberHandling.Disallow)]
    public sealed class MeshDocument
    {
        public string? File { get; set; }
        public string? Material { get; set; }
        public double[]? Translate { get; set; }
        public double? Scale { get; set; }
        public double[]? Rotate { get; set; }
    }
}
