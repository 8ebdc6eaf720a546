using QuantumRayTracing.Cli;
using QuantumRayTracing.Output;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Output;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Cli;

/// <summary>`render` with sampled light: `--area-samples`, `--vpl`, `--reference-samples`, their limits and the converged reference image.</summary>
public sealed class RenderLightsCommandTests : IDisposable
{
    private static readonly string AreaScene = Path.Combine(RepositoryPaths.Scenes, "qornell-64-area.json");
    private static readonly string TempleScene = Path.Combine(RepositoryPaths.Scenes, "temple-32.json");

    private readonly ScratchDirectory _scratch = new("qrt-lights-");

    public void Dispose() => _scratch.Dispose();

    [Theory]
    [InlineData("--area-samples", "0")]
    [InlineData("--area-samples", "4097")]
    [InlineData("--vpl", "-1")]
    [InlineData("--vpl", "4097")]
    [InlineData("--reference-samples", "-1")]
    [InlineData("--tie-break", "3")]
    [InlineData("--stop", "2")]
    public void UsageErrorsExitWithOne(string option, string value)
    {
        Assert.Equal(1, ConsoleCapture.Run(["render", AreaScene, "-e", "classical", "--size", "4", option, value, "-o", _scratch.File("x.png")]).Code);
        Assert.Empty(_scratch.FileNames());
    }

    [Fact]
    public void ReferenceWritesTheConvergedImageToo()
    {
        var output = _scratch.File("x.png");
        Assert.Equal(0, ConsoleCapture.Run(["render", AreaScene, "-e", "classical", "--size", "6", "--area-samples", "2", "--reference-samples", "8",
            "--seed", "3", "--reference", "-o", output]).Code);
        Assert.Equal(["x-converged.png", "x-difference.png", "x-reference.png", "x.png"], _scratch.FileNames());
        using var classical = new ClassicalHitSearch();
        var converged = SceneRenderer.Render(Load("qornell-64-area.json"), classical, new RenderOptions(6, 6, Seed: 3, AreaSamples: 8)).Image;
        Assert.True(ImageReader.Read(_scratch.File("x-converged.png")).Pixels.SequenceEqual(converged.Pixels));
        Assert.Equal(File.ReadAllBytes(output), File.ReadAllBytes(_scratch.File("x-reference.png")));
    }

    [Fact]
    public void ZeroReferenceSamplesSkipsTheConvergedReference()
    {
        Assert.Equal(0, ConsoleCapture.Run(["render", TempleScene, "-e", "analytic", "--size", "6", "--vpl", "2", "--reference-samples", "0",
            "--reference", "-o", _scratch.File("t.png")]).Code);
        Assert.Equal(["t-difference.png", "t-reference.png", "t.png"], _scratch.FileNames());
    }

    [Fact]
    public void SceneWithABadAreaLightExitsWithTwo()
    {
        var scene = _scratch.File("bad.json");
        File.WriteAllText(scene, File.ReadAllText(AreaScene).Replace("\"radiance\": [6, 6, 6]", "\"radiance\": [6, -6, 6]"));
        Assert.NotEqual(File.ReadAllText(AreaScene), File.ReadAllText(scene));
        Assert.Equal(ExitCodes.BadInput, ConsoleCapture.Run(["render", scene, "-e", "classical", "--size", "4", "-o", _scratch.File("x.png")]).Code);
        Assert.Equal(["bad.json"], _scratch.FileNames());
    }
}
