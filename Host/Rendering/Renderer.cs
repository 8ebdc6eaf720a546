using QuantumRayTracing.Engines;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// The one way to render: `render`, every experiment and the soak come here. It checks the engine's noise model
/// once, builds the engine's search from the options' seed, runs <see cref="SceneRenderer"/> and releases the
/// engine (a pool it was given keeps running).
/// </summary>
public static class Renderer
{
    public static RenderResult Render(Scene scene, EngineSetup engine, RenderOptions options, Passes.IRenderProgress? progress = null)
    {
        EngineFactory.CheckNoise(engine.Kind, engine.NoiseModel);
        using var search = EngineFactory.CreateSearch(engine.Kind, new SeededRandom(options.Seed), engine.Workers, engine.Search,
            engine.MaxQubits, engine.Pool, engine.Noise);
        return SceneRenderer.Render(scene, search, options, progress);
    }
}
