namespace QuantumRayTracing.Scenes;

/// <summary>
/// A light at infinity: <see cref="Direction"/> is the unit direction its light travels,
/// <see cref="Irradiance"/> (RGB, ≥ 0) what it delivers to a surface facing it squarely; a surface
/// at angle θ to it receives irradiance · cos θ.
/// </summary>
public sealed record DirectionalLight(Vec3 Direction, Vec3 Irradiance);
