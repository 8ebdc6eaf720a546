using System.Globalization;
using QuantumRayTracing.Estimates;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Scenes;

namespace QuantumRayTracing.Tests.Export;

/// <summary>
/// `qrt export pooled-search` run on jsqubits (npm, not ours): the pair register's distribution jsqubits computes from the
/// file's gates must equal the header's, which the QDK computed from its own state vector, and the header's must equal
/// Grover's closed form over the pool's rays x N pairs with the pairs the pooled round's pair test marks (each ray's table
/// under its full range) (tolerance 1e-9). Four primitives on a 2-bit grid (a power of two, so the pairs fill the register's
/// values 0..rays · N − 1) and the device construction keep a pool of three rays at 27 qubits. A dropped Toffoli must fail.
/// </summary>
public sealed class PooledSearchExportOnJsqubitsTests : IDisposable
{
    private const string Tiny = """
        {
          "image": { "width": 4, "height": 4 },
          "grid": { "integerBits": 2, "fractionBits": 0 },
          "camera": { "position": [1.5, 1.5, 0], "lookAt": [1.5, 1.5, 3] },
          "materials": { "white": { "diffuse": [0.8, 0.8, 0.8] } },
          "rectangles": [
            { "min": [0, 0, 1], "max": [2, 2, 1], "material": "white" },
            { "min": [1, 1, 2], "max": [3, 3, 2], "material": "white" },
            { "min": [0, 0, 3], "max": [3, 3, 3], "material": "white" },
            { "min": [2, 0, 1], "max": [2, 3, 3], "material": "white" }
          ]
        }
        """;

    private readonly ScratchDirectory _scratch = new("qrt-export-pooled-");

    public void Dispose() => _scratch.Dispose();

    [Theory]
    [InlineData(1)]
    [InlineData(2)]
    public void PooledSearchOnJsqubitsIsTheHeadersAndGroversClosedForm(int iterations)
    {
        var pixels = new[] { (0, 0), (3, 3), (1, 2) };
        var file = ExportCache.File(["export", "pooled-search", ExportCache.Scene(Tiny), "--pixels", .. pixels.Select(p => $"{p.Item1},{p.Item2}"),
            "--oracle", "device", "--iterations", iterations.ToString(CultureInfo.InvariantCulture)]);
        var marked = PairTest(pixels);
        Assert.True(marked.Length is > 0 and < 12, $"{marked.Length} of 12 pairs marked: the search would not move");
        var ideal = ExportedDistribution.FromHeader(file);
        ExportedDistribution.AssertAgree(ideal, ExportedDistribution.OnJsqubits(file, "pair"), "header", "jsqubits", $"r = {iterations}: ");
        ExportedDistribution.AssertAgree(ideal, ExportedDistribution.GroverClosedForm(12, marked, iterations), "header", "Grover's closed form", $"r = {iterations}: ");
        if (iterations == 1)
        {
            var difference = ExportedDistribution.HeaderDifferenceWithout(file, l => l.StartsWith("ccx ", StringComparison.Ordinal), "pair", _scratch.File("broken.qasm"), onJsqubits: true);
            Assert.True(difference > 1e-2, $"dropping the first ccx changed the distribution by only {difference}");
        }
    }

    /// <summary>The pairs ray k · 4 + p the pooled round marks: each camera ray's compact table under its full range.</summary>
    private static int[] PairTest((int X, int Y)[] pixels)
    {
        var scene = SceneLoader.Parse(Tiny, "tiny");
        var geometry = new SceneGeometry(scene);
        return [.. pixels.SelectMany((p, k) =>
        {
            var (input, _) = EstimateRay.Pixel(scene, geometry, 4, 4, p.X, p.Y, OracleConstruction.Device);
            var compact = RayTable.BuildCompact(geometry, input.Table.Ray);
            return compact.Marked(compact.FullRange).Indices.ToArray().Select(primitive => k * 4 + primitive);
        })];
    }
}
