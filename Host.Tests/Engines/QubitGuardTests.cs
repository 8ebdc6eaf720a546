using QuantumRayTracing.Bridge;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Tests.BadInput;
using QuantumRayTracing.Tests.Cli;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Rays;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Engines;

/// <summary>
/// The gate engine refuses a batch with a search wider than its qubit limit before any of it reaches
/// a bridge. The bridges here cannot start (their Node executable does not exist), so any attempt to
/// simulate would fail differently.
/// </summary>
public sealed class QubitGuardTests
{
    private static readonly BridgeOptions NoNode = new() { Node = "/nonexistent/node-for-qubit-guard-tests" };

    private static GroverRequest Request(OracleInput input) => new(input.Table.Marked(input.Window), 1, input);

    private static OracleInput CameraRay(Scene scene, int pixel)
    {
        var table = RayTable.Build(new SceneGeometry(scene), CameraRays.For(scene.Camera, 4, 4)[pixel]);
        return new OracleInput(table, table.FullRange);
    }

    [Fact]
    public void WiderSearchIsRefusedBeforeAnyBridgeStarts()
    {
        var scene = Load("qornell-8.json");
        var inputs = Enumerable.Range(0, 16).Select(p => CameraRay(scene, p)).ToArray();
        var widest = inputs.Max(i => OracleRegisters.For(i).PeakQubits);
        using var pool = new BridgePool(1, NoNode);
        var engine = new GateEngine(pool, maxQubits: widest - 1);
        var error = Assert.Throws<QubitLimitException>(() => engine.Measure(inputs.Select(Request).ToArray()));
        Assert.Equal(widest, error.Registers.PeakQubits);
        Assert.Equal(widest - 1, error.Limit);
        Assert.Contains($"needs {widest} qubits at peak", error.Message);
        Assert.Contains($"more than the limit of {widest - 1} (--max-qubits)", error.Message);
        Assert.Contains(error.Input.Table.Ray.Origin.ToString(), error.Message);
        Assert.DoesNotContain('\n', error.Message);
        Assert.Null(pool.Bridges[0].ProcessId);
    }

    [Fact]
    public void SearchAtTheLimitGoesToTheBridge()
    {
        var input = CameraRay(Load("qornell-8.json"), 5);
        using var pool = new BridgePool(1, NoNode);
        var engine = new GateEngine(pool, maxQubits: OracleRegisters.For(input).PeakQubits);
        // Past the guard, the missing Node executable is what fails.
        Assert.Throws<BridgeException>(() => engine.Measure([Request(input)]));
    }

    [Fact]
    public void WidthGrowsWithTheConstructionsRegisters()
    {
        // The guard reads the construction the request carries: compact holds one more coordinate
        // register and one flag fewer than baseline.
        var input = CameraRay(Load("qornell-8.json"), 5);
        var baseline = OracleRegisters.For(input with { Construction = OracleConstruction.Baseline });
        var compact = OracleRegisters.For(input with { Construction = OracleConstruction.Compact });
        Assert.Equal(input.Table.CoordinateBits - 1, compact.RegisterQubits - baseline.RegisterQubits);
    }

    [Fact]
    public void RenderRefusesTheSceneWithBadInputAndWritesNothing()
    {
        var scratch = Directory.CreateTempSubdirectory("qrt-guard-").FullName;
        try
        {
            var output = Path.Combine(scratch, "gate.png");
            var scene = Path.Combine(RepositoryPaths.Scenes, "qornell-8.json");
            Assert.Equal(ExitCodes.BadInput, ConsoleCapture.Run(["render", scene, "--engine", "gate", "--size", "2", "--max-qubits", "20", "-o", output]).Code);
            Assert.Empty(Directory.GetFiles(scratch));
        }
        finally
        {
            Directory.Delete(scratch, recursive: true);
        }
    }

    [Theory]
    [InlineData("0", "must be at least 1, got 0")]
    [InlineData("many", "Cannot parse argument 'many'")]
    public void MaxQubitsMustBeAPositiveNumber(string value, string problem) =>
        Outcome.Of("render", "--engine", "gate", "--max-qubits", value).AssertUsageError("--max-qubits", problem);
}
