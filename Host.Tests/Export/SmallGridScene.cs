using System.Globalization;
using QuantumRayTracing.Estimates;
using QuantumRayTracing.Intersection;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Generation;

namespace QuantumRayTracing.Tests.Export;

/// <summary>
/// Random scenes on a small grid (2 or 3 integer bits), drawn from a seed, whose searches fit a simulator of
/// at most 31 qubits: <paramref name="count"/> rectangles, two in three facing the camera, the rest facing ±x
/// or ±y, seen from a camera at the grid's front looking along +z. The same seed gives the same scene.
/// </summary>
internal static class SmallGridScene
{
    public static Scene Build(int integerBits, int count, ulong seed) =>
        SceneLoader.Parse(Json(integerBits, count, seed), $"small-grid-{integerBits}-{count}-{seed}");

    private static string Json(int integerBits, int count, ulong seed)
    {
        var random = new SeededRandom(seed).Fork(RandomStreams.Scenario).Fork(7000 + (ulong)(integerBits * 100 + count));
        var top = (1 << integerBits) - 1;
        var centre = top / 2.0;
        var builder = new SceneBuilder($"{count} random rectangles on a {integerBits}-bit grid, seed {seed}", integerBits)
            .Material("white", 0.75, 0.75, 0.75)
            .Camera([centre, centre, 0.25], [centre, centre, top], 60)
            .Light(centre, centre, 0.5, 10);
        for (var k = 0; k < count; k++)
        {
            var facing = random.NextInt(0, 2) switch { 0 or 1 => 2, _ => random.NextInt(0, 1) };
            var min = new double[3];
            var max = new double[3];
            for (var a = 0; a < 3; a++)
            {
                var low = a == 2 ? 1 : 0;
                min[a] = random.NextInt(low, top - 1);
                max[a] = random.NextInt((int)min[a] + 1, top);
            }
            max[facing] = min[facing];
            builder.Rectangle(min, max, "white");
        }
        return builder.ToJson();
    }

    /// <summary>
    /// The first pixel of a <paramref name="size"/>² image (row by row) whose camera ray marks exactly
    /// <paramref name="marked"/> primitives, or, with <paramref name="orMore"/>, at least that many; the geometry
    /// decides, not the circuit under test.
    /// </summary>
    public static (int X, int Y, int Marked) PixelMarking(Scene scene, int size, int marked, bool orMore = false)
    {
        var geometry = new SceneGeometry(scene);
        for (var y = 0; y < size; y++)
            for (var x = 0; x < size; x++)
            {
                var (input, _) = EstimateRay.Pixel(scene, geometry, size, size, x, y, OracleConstruction.Narrow);
                var count = input.Table.Marked(input.Window).MarkedCount;
                if (count == marked || (orMore && count > marked)) return (x, y, count);
            }
        throw new InvalidOperationException($"no pixel of {size}x{size} marks {marked}{(orMore ? " or more" : "")} primitives of {scene.Name}");
    }

    /// <summary>
    /// The file `qrt export search` (qasm2) writes for the scene at the first pixel of a grid-sized image whose ray marks
    /// <paramref name="marked"/> primitives (or more); r the default unless given (<see cref="ExportCache"/>: made once
    /// per test run). The header must list as many marked.
    /// </summary>
    public static string ExportSearch(int integerBits, int count, ulong seed, int marked, bool orMore = false, int? iterations = null)
    {
        var size = 1 << integerBits;
        var (x, y, found) = PixelMarking(Build(integerBits, count, seed), size, marked, orMore);
        string[] r = iterations is { } n ? ["--iterations", n.ToString(CultureInfo.InvariantCulture)] : [];
        var scene = ExportCache.Scene(Json(integerBits, count, seed));
        var file = ExportCache.File(["export", "search", scene, "--size", $"{size}", "--pixel", $"{x},{y}", .. r]);
        Assert.Equal(found, ExportedDistribution.MarkedFromHeader(file).Length);
        return file;
    }
}
