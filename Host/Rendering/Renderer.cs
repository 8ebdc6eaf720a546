using QuantumRayTracing.Engines;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// The one way to render: `render`, every experiment and the soak come here. It checks the engine's noise model
/// once and renders the image as one part or, when large, in tiles (<see cref="TiledRender"/>); the parts render here
/// or, on a seeded engine told to (<see cref="EngineSetup.ImagePartsOnCluster"/>), on a cluster's workers (<see cref="RemoteParts"/>), the same image
/// either way. The accuracy budget holds on the seeded engines; the simulator engines run their searches as configured.
/// </summary>
public static class Renderer
{
    public static RenderResult Render(Scene scene, EngineSetup engine, RenderOptions options, Passes.IRenderProgress? progress = null)
    {
        EngineFactory.CheckPrimitives(engine.Kind, scene);
        EngineFactory.CheckNoise(engine.Kind, engine.NoiseModel, engine.Device, scene.Primitives.Count);
        // The simulator engines run the searches as configured: their renders exist to run the circuits (validation,
        // clusters, the qubit guard), and the budget's classical settle would take the small images they can simulate
        // off the simulator altogether.
        if (engine.Kind.RunsQSharp) options = options with { Budget = null };
        IPartRenderer parts = engine.ImagePartsOnCluster && engine.Kind.IsSeedable && engine.Pool?.Remote is { } cluster
            ? new RemoteParts(cluster, engine.Pool.Workers, scene, engine)
            : new LocalParts(scene, engine);
        return TiledRender.Applies(options) ? TiledRender.Render(parts, options, progress) : parts.Render(options, null, progress);
    }
}
