using QuantumRayTracing.Output;
using QuantumRayTracing.Experiments;
using QuantumRayTracing.Cli;
using QuantumRayTracing.Engines;
using QuantumRayTracing.Randomness;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Search;
using QuantumRayTracing.Tests.Cli;
using QuantumRayTracing.Tests.Output;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Experiments;

/// <summary>What `bench fullstate-performance` renders and how it splits a render's time.</summary>
public sealed class FullStateBenchmarkTests : IDisposable
{
    private readonly ScratchDirectory _scratch = new("qrt-bench-fullstate-");

    public void Dispose() => _scratch.Dispose();

    [Fact]
    public void RendersTheRenderCommandsDefaultPipeline()
    {
        // Same seed and options give the same image on the analytic engine, so a different pipeline would show.
        var output = _scratch.File("default.png");
        var scene = Path.Combine(RepositoryPaths.Scenes, "qornell-8.json");
        Assert.Equal(0, ConsoleCapture.Run("render", scene, "--engine", "analytic", "--size", "12", "--seed", "3", "-o", output).Code);
        using var search = EngineFactory.CreateSearch(EngineKind.Analytic, new SeededRandom(3), 1, new QSearchOptions());
        var image = SceneRenderer.Render(Load("qornell-8.json"), search, FullStateBenchmark.DefaultPipeline(12, 3)).Image;
        Assert.True(ImageReader.Read(output).Pixels.SequenceEqual(image.Pixels));
    }

    [Fact]
    public void SimulationIsTheTimeInCallsBeyondTheirFloor()
    {
        // 10 calls of a 50 ms floor in 1.5 s of calls: 1 s of simulation over 200 runs, on 2 workers, for 100 rays.
        var row = new FullStateBenchmark.Row("s", 8, FullStateBenchmark.Variant.Current, 2, 100, TimeSpan.FromSeconds(1),
            10, TimeSpan.FromSeconds(1.5), 200, 50, double.NaN);
        Assert.Equal(1000, row.SimulationMs, 6);
        Assert.Equal(1.0 / 3, row.FloorShare, 6);
        Assert.Equal(5, row.SimulationMsPerRun, 6);
        Assert.Equal(5, row.FloorMsPerRay, 6);
        Assert.Equal(10, row.MillisecondsPerRay, 6);
    }
}
