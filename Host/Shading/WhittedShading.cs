using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Shading;

/// <summary>
/// Whitted-style local shading: diffuse albedo times (ambient + the sum over visible point lights of
/// intensity · cos θ / distance²). Mirrors contribute through the reflected point's share.
/// </summary>
public static class WhittedShading
{
    /// <summary>The radiance a surface point sends to the eye, before its pixel weight; <paramref name="visible"/>(l) says whether light l reaches it.</summary>
    public static Vec3 Radiance(Scene scene, SurfacePoint point, Func<int, bool> visible)
    {
        var albedo = scene.Primitives[point.Hit.Primitive].Material.Diffuse;
        var irradiance = new Vec3(scene.Ambient, scene.Ambient, scene.Ambient);
        for (var l = 0; l < scene.Lights.Count; l++)
        {
            if (visible(l)) irradiance += LightIrradiance.Point(point.Hit.Point, point.Normal, scene.Lights[l]);
        }
        return albedo * irradiance;
    }

    /// <summary>Display encoding of a linear radiance channel: gamma 1/2.2 (clamping to [0, 1] happens at quantisation).</summary>
    public static double Encode(double linear) => linear <= 0 ? 0 : Math.Pow(linear, 1 / 2.2);
}
