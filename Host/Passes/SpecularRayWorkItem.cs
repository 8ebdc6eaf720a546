using QuantumRayTracing.Rays;

namespace QuantumRayTracing.Passes;

/// <summary>A mirror's reflection ray, queued for the specular pass: the pixel it lights and its mirror share.</summary>
public readonly record struct SpecularRayWorkItem(int Pixel, double Mirror, Ray Ray);
