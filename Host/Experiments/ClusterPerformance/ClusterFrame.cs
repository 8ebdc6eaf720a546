using System.Diagnostics;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;

namespace QuantumRayTracing.Experiments;

/// <summary>
/// One large analytic frame rendered by this process alone and by a cluster's workers in tiles (<see cref="RemoteParts"/>):
/// each wall time, whether the images are the same bytes, and the tiles the cluster sent again.
/// </summary>
public sealed record ClusterFrame(int Size, TimeSpan Local, TimeSpan OnCluster, bool SameImage, string Where, double? LoadBefore, double? LoadAfter)
{
    /// <summary>The warm-up frame's side: tiled, so every worker takes a tile.</summary>
    public const int WarmUpSide = 1024;

    public static ClusterFrame Measure(Scene scene, int size, ulong seed, BridgePool cluster)
    {
        var options = RenderDefaults.Options(size, size, seed);
        var engine = new EngineSetup(EngineKind.Analytic, new QSearchOptions());
        var onCluster = engine with { Pool = cluster, ImagePartsOnCluster = true };
        // A tiled warm-up on each side first, so that neither time pays for compiling the renderer.
        var warmUp = RenderDefaults.Options(WarmUpSide, WarmUpSide, seed);
        Renderer.Render(scene, engine, warmUp);
        Renderer.Render(scene, onCluster, warmUp);
        var load = MachineLoad.OneMinute();
        var clock = Stopwatch.StartNew();
        var local = Renderer.Render(scene, engine, options).Image.Pixels.ToArray();
        var localTime = clock.Elapsed;
        LargeRenderCollection.Collect((long)size * size);
        clock.Restart();
        var remote = Renderer.Render(scene, onCluster, options).Image.Pixels;
        return new ClusterFrame(size, localTime, clock.Elapsed, remote.SequenceEqual(local), cluster.Where, load, MachineLoad.OneMinute());
    }
}
