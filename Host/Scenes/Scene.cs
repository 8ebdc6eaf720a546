namespace QuantumRayTracing.Scenes;

/// <summary>A validated scene: everything a render needs, in world units on <see cref="Grid"/>.</summary>
public sealed record Scene(
    string Name,
    int Width,
    int Height,
    CoordinateGrid Grid,
    Camera Camera,
    double Ambient,
    IReadOnlyList<Material> Materials,
    IReadOnlyList<PointLight> Lights,
    IReadOnlyList<Rectangle> Rectangles);
