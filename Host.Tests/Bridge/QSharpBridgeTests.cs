using System.Diagnostics;
using System.Text.Json.Nodes;
using QuantumRayTracing.Bridge;
using QuantumRayTracing.Tests.Engines;

namespace QuantumRayTracing.Tests.Bridge;

/// <summary>Every way the bridge can fail ends in a clear exception, and a dead bridge is started again once.</summary>
public sealed class QSharpBridgeTests(BridgeFixture fixture) : IClassFixture<BridgeFixture>, IDisposable
{
    /// <summary>The class's bridge: each test leaves it answering (a killed or timed-out bridge restarts).</summary>
    private readonly QSharpBridge _bridge = fixture.Bridge;
    private readonly string _scratch = Directory.CreateTempSubdirectory("qrt-bridge-").FullName;

    [Fact]
    public void ReportsTheQdkVersion()
    {
        Assert.Equal(RepositoryPaths.LockedQdkVersion, _bridge.Version()["qsharp"]!.GetValue<string>());
        Assert.Equal(RepositoryPaths.LockedQdkVersion, _bridge.QSharpVersion);
    }

    [Fact]
    public void RuntimeFailureCarriesTheQSharpMessageAndLocation()
    {
        var error = Assert.Throws<QSharpException>(() => _bridge.Run("QuantumRayTracing.Search.MeasureGroverSearch(8, [9], 1)"));
        Assert.Contains("marked index 9 is outside 0..7", error.Message);
        Assert.Contains("MeasureGroverSearch.qs", error.Location);
        // The bridge survives a Q# failure.
        Assert.Equal(["[3]"], _bridge.Run("QuantumRayTracing.Search.MeasureGroverBatch([(4, [3], 1)])"));
    }

    [Fact]
    public void ExpressionThatDoesNotCompileIsAQSharpError()
    {
        var error = Assert.Throws<QSharpException>(() => _bridge.Run("QuantumRayTracing.Search.NoSuchOperation(1)"));
        Assert.Contains("NoSuchOperation", error.Message);
    }

    [Fact]
    public void MalformedRequestsAreRejected()
    {
        Assert.Throws<BridgeRequestException>(() => _bridge.Send(new JsonObject { ["method"] = "frobnicate" }));
        Assert.Throws<BridgeRequestException>(() => _bridge.Send(new JsonObject { ["method"] = "run" }));
        Assert.Throws<BridgeRequestException>(() => _bridge.Send(new JsonObject { ["method"] = "run", ["expr"] = "Std.Math.PI()", ["shots"] = 0 }));
    }

    [Fact]
    public void KilledBridgeIsRestartedOnce()
    {
        _bridge.Version();
        var restarts = _bridge.Restarts;
        using (var process = Process.GetProcessById(_bridge.ProcessId!.Value))
        {
            process.Kill();
            process.WaitForExit();
        }
        Assert.Equal(RepositoryPaths.LockedQdkVersion, _bridge.Version()["qsharp"]!.GetValue<string>());
        Assert.Equal(restarts + 1, _bridge.Restarts);
    }

    [Fact]
    public void BridgeThatKeepsDyingGivesAClearException()
    {
        var script = Path.Combine(_scratch, "dies.mjs");
        File.WriteAllText(script, "console.error('simulated crash'); process.exit(3);\n");
        using var bridge = new QSharpBridge(new BridgeOptions { Script = script });
        var error = Assert.Throws<BridgeException>(() => bridge.Version());
        Assert.Contains("crashed twice", error.Message);
        Assert.Contains("simulated crash", error.Message);
    }

    [Fact]
    public void MissingNodeGivesAClearException()
    {
        using var bridge = new QSharpBridge(new BridgeOptions { Node = Path.Combine(_scratch, "no-such-node") });
        var error = Assert.Throws<BridgeException>(() => bridge.Version());
        Assert.Contains("Node.js", error.Message);
    }

    [Fact]
    public void SlowRequestTimesOutAndTheBridgeRecovers()
    {
        // A request that never ends, under a limit of its own: the bridge's other requests keep the default
        // limit, so however loaded the machine, only this one can time out.
        _bridge.Version();
        const string endless = "{ mutable n = 0; while n >= 0 { set n += 1; } n }";
        var error = Assert.Throws<BridgeTimeoutException>(() => _bridge.Run(endless, timeout: TimeSpan.FromSeconds(1)));
        Assert.Contains("did not answer request run within 1 s", error.Message);
        Assert.Equal(RepositoryPaths.LockedQdkVersion, _bridge.Version()["qsharp"]!.GetValue<string>());
    }

    public void Dispose() => Directory.Delete(_scratch, recursive: true);
}
