using System.Globalization;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Experiments;
using QuantumRayTracing.Output;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Tests.Cli;

namespace QuantumRayTracing.Tests.Experiments;

/// <summary>
/// `bench light-transport` at its smallest: 4x4 pixels, sets of 8 samples, 16 and 64 queries, one seed. The tables must hold the
/// renders measured (one cell rendered again here) and the slopes and queries to 1 % must follow from the table's own numbers,
/// recomputed here from the printed cells.
/// </summary>
public sealed class BenchLightTransportCommandTests : IDisposable
{
    private static readonly int[] Budgets = [16, 64];
    private static readonly string[] Estimators = ["mc", "qcoin", "mlae", "iqae", "bae"];
    private readonly ScratchDirectory _scratch = new("qrt-bench-light-transport-");

    public void Dispose() => _scratch.Dispose();

    private string Report => Path.Combine(_scratch.Path, "light-transport.md");

    private string[] Run(params string[] extra) =>
        ["bench", "light-transport", "--scenes", RepositoryPaths.Scenes, "--size", "4", "--area-samples", "8", "--queries", "16", "64", "--seeds", "1",
            "--reference-samples", "8", "--image-size", "2", "--image-queries", "16", "-o", Report, .. extra];

    [Fact]
    public void TablesHoldTheMeasuredCellsAndTheSlopesFollowFromThem()
    {
        Assert.Equal(0, ConsoleCapture.Run(Run()).Code);
        var text = File.ReadAllText(Report);
        Assert.StartsWith(GeneratedReport.MarkdownMarker(BenchLightTransportCommand.CommandText), text);

        // Every estimator at every budget, once: the cells measured and no others.
        var cells = Rows(text, "| estimator | queries per point and light | seed |");
        Assert.Equal(Estimators.SelectMany(e => Budgets.Select(q => $"{e} {q} 1")).Order(), cells.Select(c => $"{c[0]} {Number(c[1])} {c[2]}").Order());
        var exact = cells.ToDictionary(c => (c[0], (int)Number(c[1])), c => Percent(c[3]));

        // One cell rendered again outside the bench: the table holds what the render measured (4 significant digits).
        var scene = SceneLoader.Load(Path.Combine(RepositoryPaths.Scenes, "qornell-64-area.json"));
        var options = RenderDefaults.Options(4, 4, 1) with { AreaSamples = 8, Light = new LightEstimation(LightEstimator.Bae, 64) };
        var measured = Renderer.Render(scene, new EngineSetup(EngineKind.Analytic), options).LightError!.Nrmse;
        Assert.Equal(measured, exact[("bae", 64)], measured * 5e-4);

        // With one seed the geometric-mean table is the cells themselves.
        var byQueries = Rows(text, "| queries per point and light | mc |");
        Assert.Equal(Budgets.Length, byQueries.Count);
        foreach (var row in byQueries)
            for (var e = 0; e < Estimators.Length; e++)
                Assert.Equal(exact[(Estimators[e], (int)Number(row[0]))], Percent(row[e + 1]), 1e-12);

        // The slope of a line through the two printed points, and where it reaches 1 %; the printed cells carry 4 significant digits,
        // so the recomputed slope may differ by about 1e-3 and the printed one is rounded to 0.01.
        var slopes = Rows(text, "| estimator | fitted slope |").ToDictionary(r => r[0]);
        Assert.Equal(Estimators.Order(), slopes.Keys.Order());
        foreach (var e in Estimators)
        {
            var (low, high) = (exact[(e, 16)], exact[(e, 64)]);
            var slope = Math.Log(high / low) / Math.Log(64.0 / 16);
            Assert.Equal(slope, double.Parse(slopes[e][1], CultureInfo.InvariantCulture), 0.006);
            Assert.Contains("one seed", slopes[e][2]);
            if (slope >= 0) continue;
            var toOnePercent = 16 * Math.Pow(0.01 / low, 1 / slope);
            Assert.Equal(toOnePercent, Number(slopes[e][4]), toOnePercent * 0.03 + 1);
            Assert.Equal(toOnePercent is >= 16 and <= 64 ? "interpolated" : "extrapolated", slopes[e][5]);
        }

        var images = Directory.GetFiles(_scratch.Path, "*.png").Select(Path.GetFileName).ToArray();
        Assert.Equal(LightTransportExperiment.Pictures([16]).Order(), images.Select(n => n!["light-transport-".Length..^".png".Length]).Order());
        Assert.All(images, name => Assert.Contains($"({name})", text));
    }

    [Theory]
    [InlineData("--area-samples", "12", "not a power of two")]
    [InlineData("--queries", "16", "at least two distinct")]
    public void BadSettingsAreUsageErrorsWithNothingWritten(string option, string value, string message)
    {
        var args = Run().ToList();
        var at = args.IndexOf(option);
        args.RemoveRange(at + 1, option == "--queries" ? 2 : 1);
        args.Insert(at + 1, value);
        var (code, error) = ConsoleCapture.Run([.. args]);
        Assert.Equal(ExitCodes.UsageError, code);
        Assert.Contains(message, error);
        Assert.Empty(Directory.GetFiles(_scratch.Path));
    }

    // The rows under the Markdown table whose header starts with <paramref name="header"/>, split into cells.
    private static List<string[]> Rows(string text, string header) =>
        text.Split('\n').SkipWhile(line => !line.StartsWith(header, StringComparison.Ordinal)).Skip(2).TakeWhile(line => line.StartsWith('|'))
            .Select(line => line.Trim().Trim('|').Split(" | ").Select(c => c.Trim()).ToArray()).ToList();

    private static double Number(string cell) => double.Parse(cell.Replace(",", "", StringComparison.Ordinal), CultureInfo.InvariantCulture);

    private static double Percent(string cell) => Number(cell.Replace(" %", "", StringComparison.Ordinal)) / 100;
}
