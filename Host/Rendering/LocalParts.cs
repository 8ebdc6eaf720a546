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

    public int Concurrency => 1;

    public RenderResult Render(RenderOptions options, ImageWindow? window, IRenderProgress? progress)
    {
        using var search = EngineFactory.CreateSearch(_engine.Kind, new SeededRandom(options.Seed), _engine.Workers, _engine.Search,
            _engine.MaxQubits, _engine.Pool, _engine.Noise, _approximation, _engine.NoiseAware, _engine.Device);
        return SceneRenderer.Render(_scene, search, options, progress, window);
    }
}
