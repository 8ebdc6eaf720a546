using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Tests.Scenes;

/// <summary>The primitives of a scene made of rectangles only, as rectangles.</summary>
internal static class SceneRectangles
{
    public static IReadOnlyList<Rectangle> Rectangles(this Scene scene) => [.. scene.Primitives.Cast<Rectangle>()];
}
