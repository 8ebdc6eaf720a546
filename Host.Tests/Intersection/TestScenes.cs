using System.Globalization;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Tests.Intersection;

/// <summary>
/// Tiny scenes written as scene-file JSON (docs/scenes.md) and read by the real loader, so every
/// test geometry passes the same validation as a user's file.
/// </summary>
internal static class TestScenes
{
    /// <summary>One rectangle as a scene-file entry.</summary>
    public static string Rect(double x0, double y0, double z0, double x1, double y1, double z1, string material = "white") =>
        string.Create(CultureInfo.InvariantCulture,
            $$"""{ "min": [{{x0}}, {{y0}}, {{z0}}], "max": [{{x1}}, {{y1}}, {{z1}}], "material": "{{material}}" }""");

    /// <summary>
    /// A scene on a grid of <paramref name="integerBits"/>.<paramref name="fractionBits"/> with the given rectangles; materials white, grey, mirror.
    /// <paramref name="more"/> holds further top-level fields (area or directional lights), e.g. <c>"areaLights": [ … ],</c>.
    /// </summary>
    public static Scene With(int integerBits, int fractionBits, IEnumerable<string> rectangles,
        string camera = """{ "position": [4, 4, -4], "lookAt": [4, 4, 8] }""", string lights = "[]", double ambient = 0, string more = "") =>
        SceneLoader.Parse(string.Create(CultureInfo.InvariantCulture, $$"""
            {
              "image": { "width": 4, "height": 4 },
              "grid": { "integerBits": {{integerBits}}, "fractionBits": {{fractionBits}} },
              "camera": {{camera}},
              "ambient": {{ambient}},
              "materials": {
                "white": { "diffuse": [0.5, 0.6, 0.8] },
                "grey": { "diffuse": [0.8, 0.8, 0.8] },
                "mirror": { "diffuse": [0.2, 0.2, 0.2], "mirror": 0.5 }
              },
              "lights": {{lights}},
              {{more}}
              "rectangles": [ {{string.Join(",\n", rectangles)}} ]
            }
            """), "test.json");

    public static Scene With(int integerBits, int fractionBits, params string[] rectangles) =>
        With(integerBits, fractionBits, (IEnumerable<string>)rectangles);

    public static RayTable Table(Scene scene, Ray ray) => RayTable.Build(new SceneGeometry(scene), ray);

    public static Scene Load(string file) => SceneLoader.Load(Path.Combine(RepositoryPaths.Scenes, file));

    /// <summary>
    /// The closest hit computed here from the table's rows alone: a valid row whose point lies inside
    /// the rectangle's grid bounds on every axis and whose depth is in [Near, Far], smallest (depth, id).
    /// </summary>
    public static int? BruteForceClosest(RayTable table)
    {
        var geometry = table.Geometry;
        (int Depth, int Id)? best = null;
        for (var p = 0; p < table.Count; p++)
        {
            if (!table.IsValid(p)) continue;
            var inside = true;
            for (var axis = 0; axis < 3; axis++)
                inside &= geometry.Min(p, axis) <= table.Point(p, axis) && table.Point(p, axis) <= geometry.Max(p, axis);
            var depth = table.Depth(p);
            if (!inside || depth < table.Ray.Near || depth > table.Ray.Far) continue;
            if (best is not { } b || depth < b.Depth || (depth == b.Depth && p < b.Id)) best = (depth, p);
        }
        return best?.Id;
    }
}
