using System.Globalization;

namespace QuantumRayTracing.Tests.Export;

/// <summary>
/// `qrt export search|device-experiment --format qasm2` run on jsqubits (npm, not ours), whose state is sparse,
/// so circuits of 24 to 28 qubits take a fraction of a second where quantum-circuit would loop over 2^20 and more
/// basis states per gate. The index register's distribution it computes from the file's gates must equal the
/// header's, which the QDK computed from its own state vector (tolerance 1e-9; both exact up to floating
/// point), and the header must equal Grover's closed form for the header's marked set and iteration count
/// (1e-9). Rays: two random scenes on a 3-bit grid at pixels that mark none, one and several primitives, a ray
/// that marks none on a 2-bit grid with the oracle run once, and the device experiment. A dropped Toffoli and a
/// wrong iteration count must fail the same comparison.
/// </summary>
public sealed class SearchExportOnJsqubitsTests : IDisposable
{
    private readonly ScratchDirectory _scratch = new("qrt-export-jsq-");

    public void Dispose() => _scratch.Dispose();

    /// <summary>N and r as the header states them.</summary>
    private static (int Count, int Iterations) HeaderCountAndIterations(string file)
    {
        var lines = File.ReadAllLines(file);
        var scene = lines.First(l => l.StartsWith("// scene: ", StringComparison.Ordinal));
        var n = int.Parse(scene[(scene.LastIndexOf("N = ", StringComparison.Ordinal) + 4)..].Split(' ')[0], CultureInfo.InvariantCulture);
        var r = int.Parse(lines.First(l => l.StartsWith("// iterations: ", StringComparison.Ordinal))["// iterations: ".Length..].Split(' ', ';')[0], CultureInfo.InvariantCulture);
        return (n, r);
    }

    private static void AssertJsqubitsHeaderAndClosedFormAgree(string file, string what)
    {
        var ideal = ExportedDistribution.FromHeader(file);
        var simulated = ExportedDistribution.OnJsqubits(file, "index");
        ExportedDistribution.AssertAgree(ideal, simulated, "header", "jsqubits", $"{what}: ");
        var (count, iterations) = HeaderCountAndIterations(file);
        var closedForm = ExportedDistribution.GroverClosedForm(count, ExportedDistribution.MarkedFromHeader(file), iterations);
        ExportedDistribution.AssertAgree(ideal, closedForm, "header", "Grover's closed form", $"{what}: ");
    }

    [Theory]
    [InlineData(3, 12, 3UL, 0, false, null)] // a ray that hits nothing: r = 0 by default, the uniform superposition over 12
    [InlineData(3, 12, 3UL, 0, false, 2)] // the same ray with the oracle run twice: still uniform
    [InlineData(3, 12, 3UL, 1, false, null)]
    [InlineData(3, 12, 3UL, 2, true, null)]
    [InlineData(3, 7, 2UL, 1, false, null)]
    [InlineData(3, 7, 2UL, 2, true, null)]
    [InlineData(2, 6, 1UL, 0, false, 1)] // 2-bit grid, hits nothing, one iteration
    public void SearchOnJsqubitsIsTheHeadersAndGroversClosedForm(int bits, int count, ulong seed, int marked, bool orMore, int? iterations)
    {
        var file = SmallGridScene.ExportSearch(bits, count, seed, marked, orMore, iterations);
        AssertJsqubitsHeaderAndClosedFormAgree(file, $"{count} rectangles, {bits}-bit grid, seed {seed}, {marked}{(orMore ? "+" : "")} marked, r {iterations?.ToString(CultureInfo.InvariantCulture) ?? "default"}");
        if (marked == 0 && iterations is null)
            Assert.Contains("iterations: 0 (no primitive is marked: every r leaves the uniform distribution as it is, so none is run)", File.ReadAllText(file), StringComparison.Ordinal);
    }

    [Fact]
    public void DeviceExperimentOnJsqubitsIsTheHeadersAndGroversClosedForm()
    {
        var file = ExportCache.File("export", "device-experiment");
        Assert.Contains("// qubits: 28;", File.ReadAllText(file), StringComparison.Ordinal);
        AssertJsqubitsHeaderAndClosedFormAgree(file, "device experiment");
        // Dropping the first Toffoli (a load of the oracle's lookup) must break the search.
        var difference = ExportedDistribution.HeaderDifferenceWithout(file, l => l.StartsWith("ccx ", StringComparison.Ordinal), "index", _scratch.File("broken.qasm"), onJsqubits: true);
        Assert.True(difference > 1e-2, $"dropping the first ccx changed the distribution by only {difference}");
    }

    /// <summary>
    /// Qornell-8, the smallest standard scene, with the two constructions whose searches fit jsqubits: device (24
    /// qubits) and baseline (30). Its default construction's search (narrow, 34 qubits) is out of jsqubits' reach;
    /// these check the same reader and writers on the standard scene's tables and the constructions' own gates.
    /// Every camera ray of the closed box meets a wall, so each marks at least one primitive: pixel (0, 0) marks
    /// one (r = 2), (5, 5) two (r = 1, P(marked) = 1), (6, 6) another one. A dropped Toffoli must fail.
    /// </summary>
    [Theory]
    [InlineData("device", "0,0", 1)]
    [InlineData("device", "5,5", 2)]
    [InlineData("device", "6,6", 1)]
    [InlineData("baseline", "0,0", 1)]
    [InlineData("baseline", "5,5", 2)]
    public void Qornell8OnJsqubitsIsTheHeadersAndGroversClosedForm(string oracle, string pixel, int marked)
    {
        var scene = Path.Combine(RepositoryPaths.Scenes, "qornell-8.json");
        var file = ExportCache.File("export", "search", scene, "--size", "8", "--pixel", pixel, "--oracle", oracle);
        Assert.Equal(marked, ExportedDistribution.MarkedFromHeader(file).Length);
        Assert.Contains($"// oracle: {oracle} ", File.ReadAllText(file), StringComparison.Ordinal);
        AssertJsqubitsHeaderAndClosedFormAgree(file, $"Qornell-8, {oracle}, pixel {pixel}");
        if (pixel == "0,0" && oracle == "device")
        {
            var difference = ExportedDistribution.HeaderDifferenceWithout(file, l => l.StartsWith("ccx ", StringComparison.Ordinal), "index", _scratch.File("broken.qasm"), onJsqubits: true);
            Assert.True(difference > 1e-2, $"dropping the first ccx changed the distribution by only {difference}");
        }
    }

    [Fact]
    public void WrongIterationCountIsRejected()
    {
        var optimal = SmallGridScene.ExportSearch(3, 12, 3UL, 1);
        var none = SmallGridScene.ExportSearch(3, 12, 3UL, 1, iterations: 1);
        Assert.Equal(2, HeaderCountAndIterations(optimal).Iterations);
        var difference = ExportedDistribution.MaxDifference(ExportedDistribution.FromHeader(optimal), ExportedDistribution.OnJsqubits(none, "index"));
        Assert.True(difference > 0.3, $"r = 1 against the r = 2 header differs by only {difference}");
    }

    [Fact]
    public void MoreThan31QubitsAreRefused()
    {
        // jsqubits builds its masks with 32-bit shifts: qubit 32 would alias qubit 0, so the script must refuse.
        var file = _scratch.File("wide.qasm");
        File.WriteAllText(file, "OPENQASM 2.0;\ninclude \"qelib1.inc\";\nqreg q[32];\ncreg index[1];\nx q[31];\nmeasure q[0] -> index[0];\n");
        var e = Assert.ThrowsAny<Exception>(() => ExportedDistribution.OnJsqubits(file, "index"));
        Assert.Contains("at most 31 qubits", e.Message, StringComparison.Ordinal);
    }
}
