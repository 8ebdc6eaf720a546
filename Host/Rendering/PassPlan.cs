using QuantumRayTracing.Intersection;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// What every pass of one render shares: the scene, the engine, the options and the optimisations
/// built from them (one stop rule, whose draws run through all passes in order; the lattice plan; a
/// planned schedule). Closest-hit passes get <see cref="Trace"/>, visibility passes <see cref="Shadow"/>.
/// </summary>
public sealed record PassPlan(
    Scene Scene, SceneGeometry Geometry, IHitSearch Search, RenderOptions Options,
    StopRule? Stop, LatticePlan? Lattice, QSearchSchedule? Planned, IRenderProgress? Progress)
{
    /// <summary>
    /// TracePass options: #IT rounds, NeighOpt over the rays' layout (pixel and channel of each ray) when enabled;
    /// with an accuracy budget, the classical settle and the pass's <paramref name="allowance"/> of expected wrong rays, if given.
    /// </summary>
    public PassOptions Trace(IReadOnlyList<int> pixels, IReadOnlyList<int>? channels = null, double? allowance = null) =>
        new(Options.Iterations, Options.TieBreak, Options.Neighbours ? Layout(pixels, channels) : null, Stop, Lattice, Planned,
            Options.Budget is null ? null : allowance, Options.Budget is not null);

    /// <summary>
    /// DirectPass options: the shadow rounds, occluder gathering over the rays' layout when enabled, and
    /// the stop rule unless <paramref name="terminate"/> is false (every unoccluded ray then gets all its rounds); with an
    /// accuracy budget, the classical settle and the pass's <paramref name="allowance"/> of expected wrong rays, if given.
    /// </summary>
    public PassOptions Shadow(IReadOnlyList<int> pixels, IReadOnlyList<int>? channels = null, bool terminate = true, double? allowance = null) =>
        new(Options.ShadowIterations, Options.TieBreak, Options.ShadowNeighbours ? Layout(pixels, channels) : null, terminate ? Stop : null, Lattice, Planned,
            Options.Budget is null ? null : allowance, Options.Budget is not null);

    // Built only when gathering uses it: a converged reference's hundreds of samples per pixel need none.
    private PixelLayout Layout(IReadOnlyList<int> pixels, IReadOnlyList<int>? channels) =>
        new(Options.Width, Options.Height, pixels, channels);
}
