using System.Globalization;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Scenes.Meshes;

namespace QuantumRayTracing.Tests.Scenes.Meshes;

/// <summary>
/// A real mesh we did not make: the Stanford bunny as the npm package "bunny" 1.0.1 holds it, written once to
/// Fixtures/bunny.obj by a Node script that also recorded, in the file's header comment, the counts and the bounds
/// it computed itself from the package's arrays. The reader must agree with those.
/// </summary>
public sealed class BunnyTests
{
    private static readonly string Path = System.IO.Path.Combine(RepositoryPaths.Root, "Host.Tests", "Scenes", "Meshes", "Fixtures", "bunny.obj");

    /// <summary>The numbers after <paramref name="label"/> on the header line that has it.</summary>
    private static double[] Header(string label)
    {
        var line = File.ReadLines(Path).TakeWhile(l => l.StartsWith('#')).Single(l => l.Contains(label, StringComparison.Ordinal));
        return line[(line.IndexOf(label, StringComparison.Ordinal) + label.Length)..]
            .Split([' ', ';'], StringSplitOptions.RemoveEmptyEntries)
            .Select(w => double.TryParse(w, NumberStyles.Float, CultureInfo.InvariantCulture, out var x) ? x : double.NaN)
            .Where(double.IsFinite).ToArray();
    }

    [Fact]
    public void CountsAndBoundsMatchTheScriptThatWroteIt()
    {
        var file = MeshReader.Read(Path);
        // Every one of the 1,839 positions is used by a triangle (the header says so), so no vertex goes unused.
        Assert.Equal(1839, file.Mesh.Vertices.Count);
        Assert.Equal(3674, file.Mesh.Triangles.Count);
        Assert.Equal([1839, 3674, 1839, 0], Header("positions:"));
        Assert.Empty(file.Warnings);

        // "bounds over every position: min x y z max x y z", from the package's positions.
        var bounds = Header("bounds over every position: min");
        Assert.Equal((new Vec3(bounds[0], bounds[1], bounds[2]), new Vec3(bounds[3], bounds[4], bounds[5])), file.Mesh.Bounds);
        Assert.Equal((new Vec3(-4.958475, -0.003149, -3.729833), new Vec3(4.94885, 9.654748, 3.810639)), file.Mesh.Bounds);
        Assert.Equal(Header("smallest non-zero edge length:")[0], file.Mesh.SmallestEdge, 1e-15);
    }

    /// <summary>
    /// Extent 4.94885 + 4.958475 = 9.907325: I = 4 (7 &lt; 9.9 ≤ 15). Smallest edge 0.17911: F = 5 (0.179·16 = 2.87 &lt; 4 ≤
    /// 0.179·32 = 5.73). A 4.5 grid, steps of 1/32; rounding moves a vertex at most √3/2 of a step (0.027).
    /// </summary>
    [Fact]
    public void ScenesCheckSummary()
    {
        var (output, errors) = (new StringWriter(), new StringWriter());
        Assert.Equal(0, SceneCheck.Run([new FileInfo(Path)], output, errors));
        Assert.Equal("", errors.ToString());
        var line = output.ToString();
        Assert.Contains("ok: mesh, 1839 vertices, 3674 triangles, 0 degenerate dropped (0 of zero area, 0 collapsed on the grid)", line);
        Assert.Contains("bounds (-4.958475, -0.003149, -3.729833)..(4.94885, 9.654748, 3.810639)", line);
        Assert.Contains("4.5 fixed-point grid 0..15.96875 in steps of 0.03125 (moved by (4.958475, 0.003149, 3.729833); smallest edge 0.1791 = 5.7 steps)", line);
        var result = MeshCheck.Run(Path);
        Assert.InRange(result.OnGrid.LargestDisplacement, 0, Math.Sqrt(3) / 2 / 32);
    }
}
