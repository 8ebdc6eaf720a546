using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Shading;

/// <summary>
/// The irradiance each kind of light delivers to a point with unit normal n, occlusion aside. The
/// renderer's shading is then albedo · irradiance without 1/π (docs/rendering.md), for every light.
/// </summary>
public static class LightIrradiance
{
    /// <summary>Point light: intensity · cos θ / d², zero behind the surface.</summary>
    public static Vec3 Point(Vec3 at, Vec3 normal, PointLight light)
    {
        var toLight = light.Position - at;
        var distanceSquared = toLight.Dot(toLight);
        var cosine = toLight.Dot(normal) / Math.Sqrt(distanceSquared);
        return cosine > 0 ? cosine / distanceSquared * light.Intensity : Vec3.Zero;
    }

    /// <summary>Directional light: irradiance · cos θ, θ between the normal and the way back to the light; zero behind.</summary>
    public static Vec3 Directional(Vec3 normal, DirectionalLight light)
    {
        var cosine = -light.Direction.Dot(normal);
        return cosine > 0 ? cosine * light.Irradiance : Vec3.Zero;
    }

    /// <summary>
    /// One of <paramref name="count"/> samples of an area light at <paramref name="sample"/>:
    /// radiance · area · cos θ · cos θ' / d² / count, θ' at the light (both faces emit); zero behind the surface.
    /// </summary>
    public static Vec3 AreaSample(Vec3 at, Vec3 normal, AreaLight light, Vec3 sample, int count) =>
        AreaGeometry(at, normal, light, sample) / count * light.Radiance;

    /// <summary>
    /// The scalar part of an area-light sample, without the radiance and the 1/count: area · cos θ · cos θ' / d²; zero
    /// behind the surface. A sample's irradiance is this times the light's radiance.
    /// </summary>
    public static double AreaGeometry(Vec3 at, Vec3 normal, AreaLight light, Vec3 sample)
    {
        var toLight = sample - at;
        var distanceSquared = toLight.Dot(toLight);
        var distance = Math.Sqrt(distanceSquared);
        var cosine = toLight.Dot(normal) / distance;
        var cosineAtLight = Math.Abs(toLight.Dot(light.Normal)) / distance;
        return cosine > 0 && distanceSquared > 0 ? light.Area * cosine * cosineAtLight / distanceSquared : 0;
    }
}
