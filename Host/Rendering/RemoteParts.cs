using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Rendering;

/// <summary>
/// Parts rendered on a cluster's workers (<see cref="PartRequest"/>), as many at once as the workers have bridges. The
/// transport sends a part a worker failed to answer to another, so a worker lost mid-frame loses no part.
/// </summary>
public sealed class RemoteParts(IBridgeTransport transport, int concurrency, Scene scene, EngineSetup engine) : IPartRenderer
{
    private readonly string _scene = PartRequest.SceneText(scene);

    public int Concurrency { get; } = Math.Max(1, concurrency);

    public RenderResult Render(RenderOptions options, ImageWindow? window, IRenderProgress? progress) =>
        PartRequest.ReadResult(transport.Send(PartRequest.Of(_scene, engine, options, window)));
}
