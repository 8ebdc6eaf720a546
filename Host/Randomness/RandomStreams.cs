namespace QuantumRayTracing.Randomness;

/// <summary>
/// The fixed stream numbers forked from the root seed, so that each consumer's randomness is
/// independent of the others and of scheduling order. Per-search streams start at <see cref="FirstSearch"/>.
/// </summary>
public static class RandomStreams
{
    public const ulong Engine = 1;
    public const ulong Scenario = 2;

    /// <summary>QSearch's iteration counts in a render, drawn in the fixed order the passes ask for them.</summary>
    public const ulong Search = 3;

    /// <summary>The termination criterion's draws in a render.</summary>
    public const ulong Stop = 4;

    /// <summary>Area-light sample positions, one stream per sample (<see cref="SampleStreams"/>).</summary>
    public const ulong AreaLight = 5;

    /// <summary>VPL directions, one stream per pixel, surface point and VPL.</summary>
    public const ulong Vpl = 6;

    /// <summary>The area-light sample each VPL takes for its own direct light.</summary>
    public const ulong VplAreaLight = 7;

    /// <summary>Light estimation in a render: the Monte Carlo draws and the coin engine's outcomes, each from a stream forked from this one.</summary>
    public const ulong LightEstimation = 8;

    /// <summary>A tiled render's tiles: tile k's seed is drawn from stream Tiles + k (<see cref="Rendering.TiledRender"/>).</summary>
    public const ulong Tiles = 1UL << 16;

    /// <summary>Supersampling experiments: one analytic engine per estimator run, from this stream on.</summary>
    public const ulong Supersampling = 1UL << 24;

    public const ulong FirstSearch = 1UL << 32;
}
