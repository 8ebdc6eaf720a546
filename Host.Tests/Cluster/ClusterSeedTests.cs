using System.Collections.Concurrent;
using System.Text.Json.Nodes;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Cluster;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Output;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Engines;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Cluster;

/// <summary>
/// The host's seeded choices do not depend on where the Q# runs. In a scene where no ray hits anything every
/// Grover run misses whatever the simulator measures, so the requests a fullstate render sends (the searches'
/// N, marked sets and iteration counts, cut into chunks) follow from the seed alone. They are recorded where
/// bridges receive them: on this machine's bridges, and on the bridges of a two-worker cluster.
/// </summary>
public sealed class ClusterSeedTests : IDisposable
{
    // Six rectangles well to the side of a camera looking along +z: every camera ray misses them all.
    private static readonly Scene Empty = With(4, 0,
        Rect(12, 0, 0, 15, 3, 0), Rect(12, 4, 0, 15, 7, 0), Rect(12, 8, 0, 15, 11, 0),
        Rect(12, 0, 1, 15, 3, 1), Rect(12, 4, 1, 15, 7, 1), Rect(12, 8, 1, 15, 11, 1));

    private readonly ScratchDirectory _scratch = new("qrt-cluster-seed-");

    public void Dispose() => _scratch.Dispose();

    /// <summary>Records every request, as its JSON text, and runs it on <paramref name="inner"/>.</summary>
    private sealed class RecordingExecutor(IChunkExecutor inner) : IChunkExecutor
    {
        public ConcurrentBag<string> Requests { get; } = [];

        public int Capacity => inner.Capacity;

        public Task<JsonNode> Execute(JsonObject request)
        {
            Requests.Add(request.ToJsonString());
            return inner.Execute(request);
        }
    }

    /// <summary>One bridge's worth of a shared executor: the cluster's workers have one bridge each, as on two machines.</summary>
    private sealed class OneBridgeOf(IChunkExecutor shared) : IChunkExecutor
    {
        public int Capacity => 1;

        public Task<JsonNode> Execute(JsonObject request) => shared.Execute(request);
    }

    /// <summary>This machine's bridges behind the transport seam, so their requests can be recorded too.</summary>
    private sealed class LocalTransport(IChunkExecutor bridges) : IBridgeTransport
    {
        public JsonNode Send(JsonObject request) => bridges.Execute(request).GetAwaiter().GetResult();

        public RunPlace Place => RunPlace.LocalBridges(bridges.Capacity);
    }

    private RenderRunResult Render(BridgePool pool, ulong seed, string output) => RenderRun.Run(new RenderRunSettings(
        Empty, RenderDefaults.Options(4, 4, seed), new EngineSetup(EngineKind.FullState).OnBridges(pool), _scratch.File(output)));

    // Chunks of one round run at once, so their order varies: the requests are compared as sorted lists.
    private static string[] Sorted(params RecordingExecutor[] executors) => executors.SelectMany(e => e.Requests).Order(StringComparer.Ordinal).ToArray();

    private static (long Rays, SearchCost Cost) Counts(PassMetrics total) => (total.Rays, total.Cost);

    [Fact]
    public void ClusterGetsTheSameRequestsAsLocalBridges()
    {
        var geometry = new SceneGeometry(Empty);
        Assert.All(CameraRays.For(Empty.Camera, 4, 4), ray =>
        {
            var table = RayTable.Build(geometry, ray);
            Assert.Equal(0, table.Marked(table.FullRange).MarkedCount);
        });

        using var localBridges = new WorkerBridges(2);
        var (local, otherSeed) = (new RecordingExecutor(localBridges), new RecordingExecutor(localBridges));
        RenderRunResult onLocal;
        using (var pool = new BridgePool(new LocalTransport(local), 2))
            onLocal = Render(pool, seed: 11, "local.png");
        using (var pool = new BridgePool(new LocalTransport(otherSeed), 2))
            Render(pool, seed: 12, "other.png");

        // The workers run on the same two Node bridges, one each: what a worker sends them is recorded before they see it.
        var (onFirst, onSecond) = (new RecordingExecutor(new OneBridgeOf(localBridges)), new RecordingExecutor(new OneBridgeOf(localBridges)));
        RenderRunResult onCluster;
        using (var cluster = new TestCluster(120, onFirst, onSecond))
        using (var pool = ClusterBridges.Start(cluster.ConfigPath, 1))
        {
            Assert.Equal(2, pool.Workers);
            onCluster = Render(pool, seed: 11, "cluster.png");
        }

        var (requests, clusterRequests) = (Sorted(local), Sorted(onFirst, onSecond));
        Assert.True(requests.Length > 4, $"{requests.Length} requests: too few to show anything");
        Assert.True(onFirst.Requests.Count > 0 && onSecond.Requests.Count > 0, "both workers should serve chunks");
        Assert.Equal(requests, clusterRequests);
        Assert.Equal(Counts(onLocal.Figures.Total), Counts(onCluster.Figures.Total));
        Assert.Equal(RunPlace.ClusterKind, onCluster.RanOn.Kind);
        // The check can fail: another seed makes other choices.
        Assert.NotEqual(requests, Sorted(otherSeed));
    }
}
