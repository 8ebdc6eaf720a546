namespace QuantumRayTracing.Scenes;

/// <summary>A point light: position in world units, RGB intensity (radiant intensity, ≥ 0, falls off with distance squared).</summary>
public sealed record PointLight(Vec3 Position, Vec3 Intensity);
