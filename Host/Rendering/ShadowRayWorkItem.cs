namespace QuantumRayTracing.Rendering;

/// <summary>
/// A shadow ray, queued for the direct-light pass (the ray itself is computed from the point and light when read): from surface point <paramref name="Point"/> towards light
/// <paramref name="Light"/> (point lights first, then directional ones). Its layout channel is the light and
/// whether the point is primary or reflected, so gathering compares rays towards the same light from the same
/// kind of point.
/// </summary>
public readonly record struct ShadowRayWorkItem(int Point, int Light, int Pixel, int Channel);
