using QuantumRayTracing.Intersection;
using QuantumRayTracing.Passes;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// What a render does beyond the scene: image size, TracePass iterations (#IT) for primary and
/// specular rays, DirectPass rounds, tie-breaking, neighbour gathering (NeighOpt for primary and
/// specular rays, occluder gathering for shadow rays), the termination criterion and the seed of its
/// draws, and lattice-first tracing (levels of spacing 2, 4, …; 0 for none) with its cheap
/// confirmation where neighbours agree; <see cref="PlannedMiss"/>, when set, replaces Algorithm 1's
/// schedule in every other search by the cheapest fixed list missing at most that share of rays with
/// 1..<see cref="Search.ConfirmationPlanner.MaxT"/> hits. <see cref="AreaSamples"/> is S, the shadow rays per surface point
/// and area light; <see cref="Vpl"/> the virtual point lights per surface point for single-bounce indirect light (0: none).
/// <see cref="RequiredMisses"/>: the consecutive empty searches a ray its lattice neighbours do not vouch for needs before
/// the stop rule may end it (1: the paper's rule); null leaves it to the budget: 1 when <see cref="Budget"/> holds the render (its
/// rounds search more where needed), else derived from the budget's target (<see cref="AccuracyBudget.RequiredMisses"/>). <see cref="Budget"/>: the share of pixels the render may leave wrong in expectation,
/// held by budget rounds in the primary, specular and shadow passes, with rays settled classically where that is cheaper
/// (<see cref="AccuracyBudget"/>); null for none (the searches run as configured, nothing more). <see cref="SizeConfirmation"/>:
/// under a budget, each lattice level's cheap confirmation is sized by the budget (<see cref="CheapConfirmation"/>) rather
/// than the fixed <see cref="AgreedMiss"/> list. The parameters' defaults are the paper's plain pipeline; every default lives in
/// <see cref="RenderDefaults"/>, beside what `render` runs. <see cref="Light"/>: the area light estimated as a mean over each point's sample set
/// (<see cref="LightEstimation"/>); null traces every sample's shadow ray.
/// </summary>
public sealed record RenderOptions(
    int Width,
    int Height,
    int Iterations = RenderDefaults.PaperIterations,
    int ShadowIterations = DirectPass.DefaultIterations,
    TieBreak TieBreak = TieBreak.Strict,
    bool Neighbours = false,
    bool ShadowNeighbours = false,
    StopMode Stop = StopMode.Off,
    ulong Seed = 1,
    int LatticeLevels = 0,
    double AgreedMiss = RenderDefaults.FixedConfirmationMiss,
    double? PlannedMiss = null,
    int AreaSamples = RenderDefaults.AreaSamples,
    int Vpl = RenderDefaults.Vpl,
    int? RequiredMisses = 1,
    double? Budget = null,
    bool SizeConfirmation = true,
    LightEstimation? Light = null)
{
    /// <summary>What the passes read of these options.</summary>
    public PassSettings ForPasses() =>
        new(Width, Height, Iterations, ShadowIterations, TieBreak, Neighbours, ShadowNeighbours, Budget is not null, AreaSamples, Vpl, Seed, Light);


    /// <summary>
    /// The paper's plain pipeline at a size: #IT TracePass and 2 DirectPass rounds, strict ties, no gathering, no
    /// termination, no lattice. <see cref="RenderDefaults.Options"/> is what `render` runs.
    /// </summary>
    public static RenderOptions PaperPipeline(int width, int height, ulong seed = 1) => new(width, height, Seed: seed);
}
