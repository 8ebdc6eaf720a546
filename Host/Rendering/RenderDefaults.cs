namespace QuantumRayTracing.Rendering;

/// <summary>
/// The configuration `render` uses unless told otherwise, and the reference every render is compared
/// with. The defaults are the measured best (docs/render-results.md).
/// </summary>
public static class RenderDefaults
{
    public const bool Neighbours = true;
    public const bool ShadowNeighbours = true;
    public const StopMode Stop = StopMode.Exact;

    /// <summary>The most lattice levels the default uses: measured best at 128x128 (docs/optimised-tracing.md).</summary>
    public const int LatticeLevels = 4;

    /// <summary>
    /// TracePass rounds at most. With termination the stop rule ends rays, so the rounds only cap the rays
    /// that keep finding closer hits: deep scenes need more than the paper's 4 (docs/accuracy.md).
    /// </summary>
    public const int Iterations = 8;
    public const double AgreedMiss = 0.4;
    public static readonly double? PlannedMiss = null;

    /// <summary>
    /// Lattice levels for an image: the coarsest lattice keeps at least <see cref="LatticePointsPerSide"/>
    /// points along the shorter side, at most <see cref="LatticeLevels"/> levels (none below 16 pixels,
    /// where agreeing neighbours several pixels away say little about a pixel).
    /// </summary>
    public static int LatticeLevelsFor(int width, int height)
    {
        var levels = 0;
        while (levels < LatticeLevels && (LatticePointsPerSide << (levels + 1)) <= Math.Min(width, height)) levels++;
        return levels;
    }

    /// <summary>Lattice points the coarsest lattice keeps along the image's shorter side, at least.</summary>
    public const int LatticePointsPerSide = 8;

    /// <summary>The options `render` uses with no options given, at a size.</summary>
    public static RenderOptions Options(int width, int height, ulong seed = 1) => new(width, height, Iterations, Seed: seed,
        Neighbours: Neighbours, ShadowNeighbours: ShadowNeighbours, Stop: Stop,
        LatticeLevels: LatticeLevelsFor(width, height), AgreedMiss: AgreedMiss, PlannedMiss: PlannedMiss, RequiredMisses: null,
        Budget: AccuracyBudget.Target);

    /// <summary>TracePass rounds of the paper's plain pipeline (<see cref="RenderOptions.PaperPipeline"/>): the paper's table 3 reaches its floor of wrong pixels on the Qornell box at 4 to 5 passes.</summary>
    public const int PaperIterations = 4;

    /// <summary>
    /// The share of rays with 1..<see cref="Search.ConfirmationPlanner.MaxT"/> hits left the cheap confirmation where lattice neighbours agree
    /// may miss, when a render with a lattice names none and has no budget to size it (`render` names <see cref="AgreedMiss"/>).
    /// </summary>
    public const double FixedConfirmationMiss = 0.025;

    /// <summary>Shadow rays per surface point and area light: the paper's 32 (sec. 7, fig. 13).</summary>
    public const int AreaSamples = 32;

    /// <summary>VPLs per surface point: none unless asked for (the paper's fig. 14 uses 4).</summary>
    public const int Vpl = 0;

    /// <summary>Area samples and VPLs of the converged classical reference: the paper's 512.</summary>
    public const int ReferenceSamples = 512;

    /// <summary>The classical render of the same image: strict ties, no pipeline tricks (it needs none: its answers are certain).</summary>
    public static RenderOptions Reference(RenderOptions options) =>
        options with { TieBreak = Intersection.TieBreak.Strict, Neighbours = false, ShadowNeighbours = false, Stop = StopMode.Off, LatticeLevels = 0, Budget = null, Light = null };

    /// <summary>
    /// The classical reference with <paramref name="samples"/> area samples and, when the render has
    /// indirect light, as many VPLs: what the Monte Carlo estimates converge to, for the error of a
    /// render against the light itself rather than against the same samples.
    /// </summary>
    public static RenderOptions Converged(RenderOptions options, int samples) =>
        Reference(options) with { AreaSamples = samples, Vpl = options.Vpl > 0 ? samples : 0 };

    /// <summary>Whether a render samples light by Monte Carlo (area lights or VPLs), so a converged reference differs from the same-sample one.</summary>
    public static bool SamplesLight(Scenes.Scene scene, RenderOptions options) => scene.AreaLights.Count > 0 || options.Vpl > 0;

}
