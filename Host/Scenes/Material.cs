namespace QuantumRayTracing.Scenes;

/// <summary>A surface: diffuse albedo per RGB channel in [0, 1] and mirror reflectance in [0, 1].</summary>
public sealed record Material(string Name, Vec3 Diffuse, double Mirror)
{
    public bool IsMirror => Mirror > 0;
}
