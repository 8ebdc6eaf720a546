using QuantumRayTracing.Scenes.Generation;

namespace QuantumRayTracing.Tests.Export;

/// <summary>
/// `qrt export search --format qasm2` run on quantum-circuit (npm), a simulator nobody here wrote: the
/// distribution of the index register it computes from the file's gates must equal the header's ideal
/// probabilities, which the QDK computed from its own state vector. Both are exact state vectors, so the
/// tolerance is 1e-9 (floating-point residue is ~1e-14); jsqubits (the other independent simulator) must agree
/// with quantum-circuit on the same file, and the header with Grover's closed form. quantum-circuit loops over
/// every basis state of the unused qubits for each gate, so the 5-square scene's 20-qubit search takes 15 to 30 s
/// on it: the cross-check of the two simulators is the smallest search with an oracle, three walls on a 1-bit grid
/// (15 qubits, under a second), at a ray that marks one primitive with r = 1; the 5-square scene's checks (rays that
/// mark one and two, a wrong iteration count, a dropped gate) run on jsqubits, which reads the files alike and
/// takes a fraction of a second. A ray that marks none runs on quantum-circuit at its default r = 0.
/// </summary>
public sealed class OpenQasmOnQuantumCircuitTests : IDisposable
{
    private readonly ScratchDirectory _scratch = new("qrt-export-qc-");

    public void Dispose() => _scratch.Dispose();

    /// <summary>Five squares on a 2-bit grid (N = 5, not a power of two, so the preparation has rotations), seen from the front: its file (<see cref="ExportCache.Scene"/>).</summary>
    public static string TinyScene()
    {
        var json = new SceneBuilder("export check, 5 primitives, 2-bit grid", integerBits: 2)
            .Material("white", 0.75, 0.75, 0.75)
            .Camera([1.5, 1.5, 0.25], [1.5, 1.5, 3], 60)
            .Light(1.5, 1.5, 0.5, 10)
            .Rectangle([0, 0, 1], [1, 1, 1], "white")
            .Rectangle([2, 0, 2], [3, 1, 2], "white")
            .Rectangle([0, 2, 2], [1, 3, 2], "white")
            .Rectangle([0, 0, 3], [3, 3, 3], "white")
            .Rectangle([2, 2, 1], [3, 3, 1], "white")
            .ToJson();
        return ExportCache.Scene(json);
    }

    /// <summary>
    /// Three walls on a 1-bit grid (N = 3: the preparation has rotations) seen from near the left wall: the ray through
    /// pixel (0, 0) of 4x4 meets the left wall alone. Its search (r = 1) has 15 qubits, the 5-square scene's 20.
    /// </summary>
    private static string CornerScene() => ExportCache.Scene(new SceneBuilder("export check, 3 walls, 1-bit grid", integerBits: 1)
        .Material("white", 0.75, 0.75, 0.75)
        .Camera([0.1, 0.5, 0.1], [0.1, 0.5, 1], 60)
        .Light(0.5, 0.5, 0.5, 10)
        .Rectangle([0, 0, 1], [1, 1, 1], "white")
        .Rectangle([0, 0, 0], [0, 1, 1], "white")
        .Rectangle([0, 0, 0], [1, 0, 1], "white")
        .ToJson());

    /// <summary>The 5-square scene's search with these options (<see cref="ExportCache"/>: made once per test run).</summary>
    private static string Export(params string[] options) => ExportCache.File(["export", "search", TinyScene(), "--size", "4", .. options]);

    [Fact]
    public void SearchOnQuantumCircuitIsTheHeadersIdealAndJsqubits()
    {
        var file = ExportCache.File("export", "search", CornerScene(), "--size", "4", "--pixel", "0,0");
        Assert.Contains("// qubits: 15;", File.ReadAllText(file), StringComparison.Ordinal);
        Assert.Equal([1], ExportedDistribution.MarkedFromHeader(file));
        var ideal = ExportedDistribution.FromHeader(file);
        var simulated = ExportedDistribution.OnQuantumCircuit(file, "index");
        ExportedDistribution.AssertAgree(ideal, simulated, "header", "quantum-circuit", "3 walls, pixel 0,0 (marks 1 of 3): ");
        // The second independent simulator reads the same file alike (it checks the other circuits alone).
        var sparse = ExportedDistribution.OnJsqubits(file, "index");
        ExportedDistribution.AssertAgree(simulated, sparse, "quantum-circuit", "jsqubits", "3 walls, pixel 0,0 (marks 1 of 3): ");
        // r = 1 at one marked of three: P(marked) = sin²(3θ) = 25/27, far above uniform (1/3).
        AssertAmplifiedAsGroversClosedForm(ideal, file, 3, "0,0");
    }

    [Fact]
    public void OneMarkedOnJsqubitsIsTheHeadersIdeal()
    {
        var file = Export("--pixel", "3,0");
        var ideal = ExportedDistribution.FromHeader(file);
        Assert.Single(ExportedDistribution.MarkedFromHeader(file));
        ExportedDistribution.AssertAgree(ideal, ExportedDistribution.OnJsqubits(file, "index"), "header", "jsqubits", "pixel 3,0 (marks 1 of 5): ");
        AssertAmplifiedAsGroversClosedForm(ideal, file, 5, "3,0");
    }

    [Fact]
    public void TwoMarkedOnJsqubitsIsTheHeadersIdeal()
    {
        var file = Export("--pixel", "0,0");
        var ideal = ExportedDistribution.FromHeader(file);
        Assert.Equal(2, ExportedDistribution.MarkedFromHeader(file).Length);
        ExportedDistribution.AssertAgree(ideal, ExportedDistribution.OnJsqubits(file, "index"), "header", "jsqubits", "pixel 0,0 (marks 2 of 5): ");
        AssertAmplifiedAsGroversClosedForm(ideal, file, 5, "0,0");
    }

    /// <summary>The search amplifies (the most likely value far above uniform, 1/<paramref name="count"/>, so the check is not of a flat distribution), as Grover's closed form says for r = 1.</summary>
    private static void AssertAmplifiedAsGroversClosedForm(IReadOnlyDictionary<int, double> ideal, string file, int count, string pixel)
    {
        Assert.True(ideal.Values.Max() > 0.35, $"pixel {pixel}: no amplified value in {string.Join(' ', ideal)}");
        var closedForm = ExportedDistribution.GroverClosedForm(count, ExportedDistribution.MarkedFromHeader(file), 1);
        ExportedDistribution.AssertAgree(ideal, closedForm, "header", "Grover's closed form", $"pixel {pixel}: ");
    }

    /// <summary>
    /// A ray that hits nothing, at the default r = 0 (the preparation alone; 17 qubits, a few seconds). The same ray
    /// with the oracle run once (20 qubits, over a minute here on a shared machine) is checked on jsqubits instead.
    /// </summary>
    [Fact]
    public void RayThatHitsNothingOnQuantumCircuitIsUniform()
    {
        // Six random rectangles on a 2-bit grid; the geometry, not the circuit, picks a pixel whose ray meets none.
        var file = SmallGridScene.ExportSearch(2, 6, 1, 0);
        var ideal = ExportedDistribution.FromHeader(file);
        var simulated = ExportedDistribution.OnQuantumCircuit(file, "index");
        ExportedDistribution.AssertAgree(ideal, simulated, "header", "quantum-circuit");
        Assert.Contains("iterations: 0 (no primitive is marked", File.ReadAllText(file), StringComparison.Ordinal);
        // Nothing marked: 1/6 on each of the six primitives.
        var uniform = ExportedDistribution.GroverClosedForm(6, [], 0);
        Assert.True(ExportedDistribution.MaxDifference(ideal, uniform) <= ExportedDistribution.Tolerance, $"header {string.Join(' ', ideal)} is not uniform over 6");
    }

    [Fact]
    public void WrongIterationCountIsRejected()
    {
        var optimal = Export("--pixel", "3,0");
        var none = Export("--pixel", "3,0", "--iterations", "0");
        var difference = ExportedDistribution.MaxDifference(ExportedDistribution.FromHeader(optimal), ExportedDistribution.OnJsqubits(none, "index"));
        Assert.True(difference > 0.5, $"r = 0 against the r = 1 header differs by only {difference}");
    }

    [Fact]
    public void DroppedGateIsRejected()
    {
        var file = Export("--pixel", "3,0");
        var difference = ExportedDistribution.HeaderDifferenceWithout(file, l => l.StartsWith("ry(", StringComparison.Ordinal), "index", _scratch.File("broken.qasm"), onJsqubits: true);
        Assert.True(difference > 1e-3, $"dropping the first ry changed the distribution by only {difference}");
    }

    [Fact]
    public void DirectCoinOnQuantumCircuitIsTheHeadersIdealAndGroversClosedForm()
    {
        var file = ExportCache.File("export", "coin", "--mean", "0.3", "--k", "2");
        var ideal = ExportedDistribution.FromHeader(file);
        Assert.True(ExportedDistribution.MaxDifference(ideal, ExportedDistribution.OnQuantumCircuit(file, "coin")) <= ExportedDistribution.Tolerance);
        // sin²θ = 0.3, k = 2: heads with probability sin²(5θ).
        var heads = Math.Pow(Math.Sin(5 * Math.Asin(Math.Sqrt(0.3))), 2);
        Assert.Equal(heads, ideal[1], 1e-9);
    }

    [Fact]
    public void MeanCoinOnQuantumCircuitIsTheHeadersIdealAndGroversClosedForm()
    {
        double[] values = [0.05, 0.2, 0.1, 0.032];
        var file = ExportCache.File(["export", "coin", "--values", .. values.Select(v => v.ToString(System.Globalization.CultureInfo.InvariantCulture)), "--k", "1"]);
        var ideal = ExportedDistribution.FromHeader(file);
        Assert.True(ExportedDistribution.MaxDifference(ideal, ExportedDistribution.OnQuantumCircuit(file, "coin")) <= ExportedDistribution.Tolerance);
        // Bit 2 is the coin: heads with probability sin²(3θ), sin²θ the mean value, whatever the subpixel bits.
        var heads = Math.Pow(Math.Sin(3 * Math.Asin(Math.Sqrt(values.Average()))), 2);
        Assert.Equal(heads, ideal.Where(e => (e.Key & 4) != 0).Sum(e => e.Value), 1e-9);
    }
}
