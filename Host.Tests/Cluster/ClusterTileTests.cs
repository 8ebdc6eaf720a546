using System.Text.Json.Nodes;
using Microsoft.Extensions.Time.Testing;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Cluster;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Noise;
using QuantumRayTracing.Output;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Cluster;

/// <summary>
/// Image parts of the seeded engines rendered on a cluster's workers (<see cref="RemoteParts"/>, <see cref="WorkerExecutor"/>):
/// through the wire format alone, on two Orleans workers, and with a worker that dies holding a tile, the image, the counts and
/// the expected wrong pixels are the local render's, byte for byte.
/// </summary>
public sealed class ClusterTileTests
{
    private static readonly Scene Qornell = Load("qornell-64.json");

    // Small tiles on a small image, so that every edge, border and clipped corner occurs (as in TiledRenderTests).
    private const int Tile = 32;

    private static RenderOptions Options(ulong seed) => RenderDefaults.Options(96, 80, seed);

    private static void AssertSameRender(RenderResult local, RenderResult remote)
    {
        Assert.Equal(local.Image.Pixels.ToArray(), remote.Image.Pixels.ToArray());
        Assert.Equal(local.Total.IntersectionsConservative, remote.Total.IntersectionsConservative);
        Assert.Equal(local.Total.Rays, remote.Total.Rays);
        Assert.Equal(local.Budget.ExpectedWrongPixels, remote.Budget.ExpectedWrongPixels);
        Assert.Equal(local.Passes.Select(p => p.Name), remote.Passes.Select(p => p.Name));
    }

    public static TheoryData<EngineKind, double> Engines => new()
    {
        { EngineKind.Analytic, 0 }, { EngineKind.Classical, 0 }, { EngineKind.Bvh, 0 }, { EngineKind.Randomized, 0 },
        { EngineKind.Analytic, 1e-3 }, // the noise model and its oracle travel with the part
    };

    /// <summary>Every part through the wire format and a worker's executor, in this process: the tiled and the untiled image.</summary>
    [Theory]
    [MemberData(nameof(Engines))]
    public void PartsThroughTheWireGiveTheLocalImage(EngineKind kind, double noise) =>
        AssertPartsThroughTheWire(new EngineSetup(kind) { Noise = noise == 0 ? null : NoiseModel.Depolarizing(noise), IdealPlan = noise > 0 });

    /// <summary>A device model (gate rates and readout error) travels with the part as the Pauli model does.</summary>
    [Fact]
    public void ADeviceModelTravelsWithThePart() =>
        AssertPartsThroughTheWire(new EngineSetup(EngineKind.Analytic) { Device = new DeviceNoiseModel(1e-4, 1e-3, 0.02, 0.04), IdealPlan = true });

    private static void AssertPartsThroughTheWire(EngineSetup engine)
    {
        var wire = new WireTransport(new WorkerExecutor(new EchoExecutor()));
        var (local, remote) = (new LocalParts(Qornell, engine), new RemoteParts(wire, 3, Qornell, engine));

        AssertSameRender(TiledRender.Render(local, Options(7), tileSize: Tile), TiledRender.Render(remote, Options(7), tileSize: Tile));
        AssertSameRender(local.Render(Options(8), null, null), remote.Render(Options(8), null, null));
        Assert.Equal(ImageTiles.Of(96, 80, Tile, 0).Count + 1, wire.Requests); // every tile, then the whole image, once each
    }

    /// <summary>A worker given a part it cannot read answers with a request error, which the render raises rather than trying another worker.</summary>
    [Fact]
    public async Task AnUnreadablePartIsARequestError()
    {
        var executor = new WorkerExecutor(new EchoExecutor());
        var request = PartRequest.Of(PartRequest.SceneText(Qornell), new EngineSetup(EngineKind.Classical), Options(1), null);
        request["options"] = new JsonObject { ["Width"] = "wide" };
        var error = await Assert.ThrowsAsync<BridgeRequestException>(() => executor.Execute(request));
        Assert.StartsWith("renderPart: the request cannot be read", error.Message);
    }

    // Two lit rectangles, off centre, across the corner where the four tiles of a 1024x1024 frame meet: every tile holds
    // edges of both, and no two tiles look alike. A quarter of Qornell's work per pixel, which a frame this size multiplies.
    private static readonly Scene Across = With(4, 0, [Rect(2, 2, 8, 7, 6, 8), Rect(3, 3, 6, 5, 5, 6, "grey")],
        lights: """[{ "position": [6, 12, 0], "intensity": [40, 40, 40] }]""", ambient: 0.1);

    /// <summary>
    /// `render`'s path (<see cref="Renderer"/> with a cluster's bridges) on two workers at 1024x1024, the smallest frame
    /// that is tiled (<see cref="TiledRender.Applies"/>), in 512x512: the local image, and both workers served tiles. Q# chunks
    /// still reach the bridges behind each worker.
    /// </summary>
    [Fact]
    public void ATiledFrameOnTwoWorkersIsTheLocalFrame()
    {
        var (first, second) = (new EchoExecutor(), new EchoExecutor());
        using var cluster = new TestCluster(120, new WorkerExecutor(first), new WorkerExecutor(second));
        using var pool = ClusterBridges.Start(cluster.ConfigPath, 1);
        var options = RenderDefaults.Options(1024, 1024, 3);
        Assert.True(TiledRender.Applies(options) && !TiledRender.Applies(options with { Height = 1023 }));
        var engine = new EngineSetup(EngineKind.Analytic);

        var remote = Renderer.Render(Across, engine.OnBridges(pool), options);
        var local = Renderer.Render(Across, engine, options);

        AssertSameRender(local, remote);
        var quarters = new[] { (0, 0), (512, 0), (0, 512), (512, 512) }
            .Select(corner => string.Concat(Enumerable.Range(0, 512 * 512).Select(k => local.Image.GetPixel(corner.Item1 + k % 512, corner.Item2 + k / 512))))
            .ToArray();
        Assert.Equal(4, quarters.Distinct().Count()); // a tile in another's place would show
        Assert.True(cluster.Served(0) > 0 && cluster.Served(1) > 0, $"tiles served: {cluster.Served(0)} and {cluster.Served(1)}; both workers should take some");
        Assert.Equal(4, cluster.Served(0) + cluster.Served(1));
        Assert.Equal(RunPlace.ClusterKind, EngineFactory.Place(EngineKind.Analytic, pool, 1).Kind);
        Assert.Equal("Request(1)", Assert.Single(pool.Bridges[0].Run("Request(1)"))); // other requests still go to the bridges
    }

    /// <summary>A worker that dies with a tile in hand loses nothing: the tile is rendered again on the other worker, the image is the local one.</summary>
    [Fact]
    public async Task AWorkerKilledMidFrameLosesNothing()
    {
        const double chunkSeconds = 5;
        var dying = new DyingExecutor();
        using var cluster = new TestCluster(chunkSeconds, dying, new WorkerExecutor(new EchoExecutor()));
        dying.Silo = cluster.Silos[0];
        var clock = new FakeTimeProvider();
        using var transport = ClusterTransport.Connect(ClusterConfig.Load(cluster.ConfigPath), clock);
        var engine = new EngineSetup(EngineKind.Analytic);
        var remote = new RemoteParts(transport, transport.Capacity, Qornell, engine);

        var run = Task.Run(() => TiledRender.Render(remote, Options(11), tileSize: Tile));
        TestCluster.WaitPastTheFaultyWorker(run, transport, clock, cluster.SiloAddress(0), cluster.SiloAddress(1), chunkSeconds, () => "the tiled render unfinished");

        AssertSameRender(TiledRender.Render(new LocalParts(Qornell, engine), Options(11), tileSize: Tile), await run);
        Assert.True(dying.Calls >= 1, "the dying worker was never given a tile, so the test proved nothing");
        Assert.True(transport.Retries >= 1, "no tile was sent again, so the test proved nothing");
    }

    // A worker's executor reached through the wire format: each request and answer written as text and read back.
    private sealed class WireTransport(IChunkExecutor worker) : IBridgeTransport
    {
        private int _requests;

        public int Requests => Volatile.Read(ref _requests);

        public RunPlace Place => RunPlace.NoBridges;

        public JsonNode Send(JsonObject request)
        {
            Interlocked.Increment(ref _requests);
            var sent = (JsonObject)JsonNode.Parse(request.ToJsonString())!;
            return JsonNode.Parse(worker.Execute(sent).GetAwaiter().GetResult().ToJsonString())!;
        }
    }
}
