using QuantumRayTracing.Passes;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Tests.Output;

namespace QuantumRayTracing.Tests.Cli;

/// <summary>`render --light-estimator` and `--light-queries`: the default unchanged, the printed light error, and the refusals.</summary>
public sealed class RenderLightEstimatorCommandTests : IDisposable
{
    private static readonly string AreaScene = Path.Combine(RepositoryPaths.Scenes, "qornell-64-area.json");
    private static readonly string PointScene = Path.Combine(RepositoryPaths.Scenes, "qornell-8.json");

    private readonly ScratchDirectory _scratch = new("qrt-light-estimator-");

    public void Dispose() => _scratch.Dispose();

    private (int Code, string Out) Render(params string[] options) =>
        ConsoleCapture.RunCapturingOutput(["render", .. options, "--size", "8", "--reference-samples", "0"]) is var r ? (r.Code, r.Output) : default;

    [Fact]
    public void McWithoutQueriesIsTheTracedRender()
    {
        Assert.Equal(0, Render(AreaScene, "--seed", "4", "-o", _scratch.File("a.png")).Code);
        var (code, _) = Render(AreaScene, "--seed", "4", "--light-estimator", "mc", "-o", _scratch.File("b.png"));
        Assert.Equal(0, code);
        Assert.Equal(File.ReadAllBytes(_scratch.File("a.png")), File.ReadAllBytes(_scratch.File("b.png")));
    }

    [Theory]
    [InlineData("mc")]
    [InlineData("qcoin")]
    [InlineData("mlae")]
    [InlineData("iqae")]
    [InlineData("bae")]
    public void EstimatedLightRecordsItsErrorAndItsPass(string estimator)
    {
        var json = _scratch.File("x.json");
        var (code, _) = Render(AreaScene, "--light-estimator", estimator, "--light-queries", "64", "-o", _scratch.File("x.png"), "--json", json);
        Assert.Equal(0, code);
        var text = File.ReadAllText(json);
        Assert.Contains($"area light {estimator}", text);
        Assert.Contains("lightError", text, StringComparison.OrdinalIgnoreCase);
    }

    [Theory]
    [InlineData("fullstate", "qcoin", "--area-samples", "32")]
    [InlineData("gate", "mc", "--light-queries", "64")]
    [InlineData("classical", "bae", "--area-samples", "32")]
    [InlineData("analytic", "qcoin", "--area-samples", "24")]
    [InlineData("analytic", "qcoin", "--vpl", "2")]
    [InlineData("analytic", "mlae", "--noise", "0.001")]
    public void EnginesAndSettingsThatCannotRunItAreRefusedInOneLine(string engine, string estimator, string option, string value)
    {
        var run = ConsoleCapture.Run(["render", AreaScene, "-e", engine, "--light-estimator", estimator, option, value, "--size", "4", "-o", _scratch.File("x.png")]);
        Assert.NotEqual(0, run.Code);
        Assert.Single(run.Error.Trim().Split('\n'));
        Assert.Contains($"--light-estimator {estimator}", run.Error);
        Assert.Empty(_scratch.FileNames());
    }

    [Fact]
    public void VplRefusalSaysWhatIsMissingAndWhatRuns()
    {
        var run = ConsoleCapture.Run(["render", AreaScene, "--light-estimator", "bae", "--vpl", "2", "--size", "4", "-o", _scratch.File("x.png")]);
        Assert.Equal(ExitCodes.BadInput, run.Code);
        Assert.Contains("VPL light is not estimated yet", run.Error);
        Assert.Contains("coin per channel", run.Error);
        Assert.Contains("--light-estimator mc without --light-queries", run.Error);
        Assert.Empty(_scratch.FileNames());
        // What the message offers runs: Monte Carlo without --light-queries traces every VPL.
        Assert.Equal(0, ConsoleCapture.Run(["render", AreaScene, "--light-estimator", "mc", "--vpl", "2", "--size", "4", "--reference-samples", "0", "-o", _scratch.File("x.png")]).Code);
    }

    [Fact]
    public void ASceneWithoutAreaLightsIsRefused()
    {
        var run = ConsoleCapture.Run(["render", PointScene, "--light-estimator", "qcoin", "--size", "4", "-o", _scratch.File("x.png")]);
        Assert.NotEqual(0, run.Code);
        Assert.Contains("no area lights", run.Error);
        Assert.Empty(_scratch.FileNames());
    }

    [Theory]
    [InlineData("3")]
    [InlineData("65537")]
    [InlineData("-1")]
    public void LightQueriesOutOfRangeAreAUsageError(string queries)
    {
        var run = ConsoleCapture.Run(["render", AreaScene, "--light-estimator", "qcoin", "--light-queries", queries, "--size", "4", "-o", _scratch.File("x.png")]);
        Assert.Equal(1, run.Code);
        Assert.Contains("--light-queries", run.Error);
        Assert.Empty(_scratch.FileNames());
    }
}
