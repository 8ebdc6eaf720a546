using QuantumRayTracing.Engines;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// Parts rendered in this process: each on a search of its own, built from the part's seed and released after it. The one
/// place an engine's search is built for a render, for `render`, the experiments and a cluster worker alike.
/// </summary>
public sealed class LocalParts : IPartRenderer
{
    private readonly Scene _scene;
    private readonly EngineSetup _engine;
    private readonly Noise.DepolarizingApproximation? _approximation;

    public LocalParts(Scene scene, EngineSetup engine)
    {
        (_scene, _engine) = (scene, engine);
        // The noise approximation counts the scene's circuit once, for every part.
        _approximation = engine.Kind.ApproximatesNoise && engine.IsNoisy ? EngineFactory.Approximation(engine.NoiseOracle, scene) : null;
    }

    public int Concurrency => TilesAtOnce(_engine.Kind);

    /// <summary>
    /// Tiles rendered at once here: two on an engine searching in this process, so the stretches of one tile that run in
    /// order on one core (a block's outcomes observed, NeighOpt's sweep, points taken in pixel order) run beside the other
    /// tile's work on all cores; one on the simulator engines, whose searches go through the Q# bridges. Each tile renders
    /// the same whenever it runs, so the image does not change, only how many tiles' work is held at once.
    /// </summary>
    public static int TilesAtOnce(EngineKind kind) => kind.RunsQSharp ? 1 : Math.Min(2, Environment.ProcessorCount);

    public RenderResult Render(RenderOptions options, ImageWindow? window, IRenderProgress? progress)
    {
        using var search = EngineFactory.CreateSearch(_engine, new SeededRandom(options.Seed), _approximation);
        return SceneRenderer.Render(_scene, search, options, progress, window);
    }
}
