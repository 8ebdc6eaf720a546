using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// A rough forecast of a gate-engine render's wall time, so a soak can skip the renders that would take
/// hours. The gate engine's Grover iteration costs about N² · 1.7 µs (<see cref="Engines.GateEngine.MaxCostPerCall"/>:
/// every table lookup touches every row of the N-amplitude state), and QSearch spends a few times sqrt N
/// iterations per ray and round, so a ray costs about N^2.5 times <see cref="SecondsPerRayUnit"/>, fitted
/// to qornell-64 at 4x4 (49 rays, 13 s of simulation). Rays are estimated from the pixels and the lights:
/// one primary ray, one shadow ray per point or directional light and one per area light and sample,
/// and with VPLs those again per VPL. Mirrors and empty pixels make the estimate high rather than low.
/// </summary>
public static class GateCostEstimate
{
    /// <summary>Seconds per ray and N^2.5.</summary>
    public const double SecondsPerRayUnit = 8e-6;

    /// <summary>The estimated rays of a render of <paramref name="scene"/> with <paramref name="options"/>.</summary>
    public static long Rays(Scene scene, RenderOptions options)
    {
        var shadowRays = scene.Lights.Count + scene.DirectionalLights.Count + (long)scene.AreaLights.Count * options.AreaSamples;
        var perPixel = 1 + shadowRays + (long)options.Vpl * (1 + shadowRays);
        return (long)options.Width * options.Height * perPixel;
    }

    public static TimeSpan Of(Scene scene, RenderOptions options) =>
        TimeSpan.FromSeconds(Rays(scene, options) * Math.Pow(scene.Primitives.Count, 2.5) * SecondsPerRayUnit);
}
