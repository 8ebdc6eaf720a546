using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Shading;

/// <summary>
/// One connection from a surface point to a light: the shadow ray that decides it and the irradiance
/// (RGB) it delivers to the point when that ray is unoccluded.
/// </summary>
public readonly record struct ShadowSample(Ray Ray, Vec3 Irradiance);
