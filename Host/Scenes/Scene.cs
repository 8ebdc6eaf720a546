namespace QuantumRayTracing.Scenes;

/// <summary>
/// A validated scene: everything a render needs, in world units on <see cref="Grid"/>. <see cref="Lights"/>
/// are the point lights; area and directional lights are listed apart (none in older scene files).
/// </summary>
public sealed record Scene(
    string Name,
    int Width,
    int Height,
    CoordinateGrid Grid,
    Camera Camera,
    double Ambient,
    IReadOnlyList<Material> Materials,
    IReadOnlyList<PointLight> Lights,
    IReadOnlyList<Primitive> Primitives)
{
    public IReadOnlyList<AreaLight> AreaLights { get; init; } = [];

    public IReadOnlyList<DirectionalLight> DirectionalLights { get; init; } = [];

    /// <summary>How the scene's triangles were put on <see cref="Grid"/>; null for a scene of rectangles alone.</summary>
    public TriangleQuantisation? Quantisation { get; init; }

    /// <summary>For a scene framed around a bare model file, the scene file it was loaded from, for the user to copy; null otherwise.</summary>
    public string? FramingText { get; init; }
}
