using QuantumRayTracing.Engines;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// The one way to render: `render`, every experiment and the soak come here. It checks the engine's noise model
/// once, builds the engine's search from the options' seed, runs <see cref="SceneRenderer"/> and releases the
/// engine (a pool it was given keeps running). The accuracy budget holds on the seeded engines; the simulator engines
/// run their searches as configured.
/// </summary>
public static class Renderer
{
    public static RenderResult Render(Scene scene, EngineSetup engine, RenderOptions options, Passes.IRenderProgress? progress = null)
    {
        EngineFactory.CheckNoise(engine.Kind, engine.NoiseModel);
        // The simulator engines run the searches as configured: their renders exist to run the circuits (validation,
        // clusters, the qubit guard), and the budget's classical settle would take the small images they can simulate
        // off the simulator altogether.
        if (engine.Kind.RunsQSharp) options = options with { Budget = null };
        var approximation = engine.Kind.ApproximatesNoise && !engine.NoiseModel.IsNoiseless ? EngineFactory.Approximation(engine.NoiseOracle, scene) : null;
        IHitSearch Search(RenderOptions o) => EngineFactory.CreateSearch(engine.Kind, new SeededRandom(o.Seed), engine.Workers, engine.Search,
            engine.MaxQubits, engine.Pool, engine.Noise, approximation, engine.NoiseAware);
        if (TiledRender.Applies(options)) return TiledRender.Render(scene, Search, options, progress);
        using var search = Search(options);
        return SceneRenderer.Render(scene, search, options, progress);
    }
}
