using QuantumRayTracing.Intersection;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Passes;

/// <summary>
/// What every pass of one render shares: the scene, the engine, the settings the passes read and the optimisations
/// built from them (one stop rule, whose draws run through all passes in order; the lattice plan; a
/// planned schedule). Closest-hit passes get <see cref="Trace"/>, visibility passes <see cref="Shadow"/>.
/// </summary>
public sealed record PassPlan(
    Scene Scene, SceneGeometry Geometry, IHitSearch Search, PassSettings Settings,
    StopRule? Stop, LatticePlan? Lattice, QSearchSchedule? Planned, IRenderProgress? Progress)
{
    /// <summary>
    /// TracePass options: #IT rounds, NeighOpt over the rays' layout (pixel and channel of each ray) when enabled;
    /// with an accuracy budget, the classical settle and the pass's <paramref name="allowance"/> of expected wrong rays, if given.
    /// </summary>
    public PassOptions Trace(IReadOnlyList<int> pixels, IReadOnlyList<int>? channels = null, double? allowance = null) =>
        new(Settings.Iterations, Settings.TieBreak, Settings.Neighbours ? Layout(pixels, channels) : null, Stop, Lattice, Planned,
            Settings.Budgeted ? allowance : null, Settings.Budgeted);

    /// <summary>
    /// DirectPass options: the shadow rounds, occluder gathering over the rays' layout when enabled, and
    /// the stop rule unless <paramref name="terminate"/> is false (every unoccluded ray then gets all its rounds); with an
    /// accuracy budget, the classical settle and the pass's <paramref name="allowance"/> of expected wrong rays, if given.
    /// </summary>
    public PassOptions Shadow(IReadOnlyList<int> pixels, IReadOnlyList<int>? channels = null, bool terminate = true, double? allowance = null) =>
        new(Settings.ShadowIterations, Settings.TieBreak, Settings.ShadowNeighbours ? Layout(pixels, channels) : null, terminate ? Stop : null, Lattice, Planned,
            Settings.Budgeted ? allowance : null, Settings.Budgeted);

    // Built only when gathering uses it: a converged reference's hundreds of samples per pixel need none.
    private PixelLayout Layout(IReadOnlyList<int> pixels, IReadOnlyList<int>? channels) =>
        new(Settings.Width, Settings.Height, pixels, channels);
}
