using QuantumRayTracing.Engines;
using QuantumRayTracing.Metrics;
using QuantumRayTracing.Output;
using QuantumRayTracing.Passes;
using QuantumRayTracing.Rendering;
using QuantumRayTracing.Scenes;
using QuantumRayTracing.Search;
using static QuantumRayTracing.Tests.Intersection.TestScenes;

namespace QuantumRayTracing.Tests.Rendering;

/// <summary>
/// <see cref="RenderRun"/> called as a library, without the command line: the files it writes hold the images it
/// returns, its error figures are those of the images, the same settings give the same bytes, and a search too
/// wide for the simulator stops the run before any file is written.
/// </summary>
public sealed class RenderRunTests : IDisposable
{
    private static readonly Scene Qornell8 = Load("qornell-8.json");

    private readonly ScratchDirectory _scratch = new("qrt-render-run-");

    public void Dispose() => _scratch.Dispose();

    // One pass of the randomized engine misses hits, so the render and its reference differ in some pixels.
    private RenderRunSettings Randomized(string output, ulong seed = 5) => new(Qornell8, new RenderOptions(16, 16, Iterations: 1, Seed: seed),
        new EngineSetup(EngineKind.Randomized), _scratch.File(output), WithReference: true);

    private static (long Rays, int Iterations, SearchCost Cost, long TableRows, long UpdatedPixels) Counts(PassMetrics pass) =>
        (pass.Rays, pass.Iterations, pass.Cost, pass.TableRows, pass.UpdatedPixels);

    [Fact]
    public void WritesTheImagesItReturnsAndMeasuresTheirDifference()
    {
        var settings = Randomized("r.png");
        var run = RenderRun.Run(settings);

        Assert.Equal(["r-difference.png", "r-reference.png", "r.png"], _scratch.FileNames());
        Assert.Equal(settings.Files, run.Figures.Written);
        Assert.Equal(run.Render.Image.Pixels.ToArray(), ImageReader.Read(settings.Files[0]).Pixels.ToArray());
        Assert.Equal(run.Reference.Image.Pixels.ToArray(), ImageReader.Read(settings.Files[1]).Pixels.ToArray());

        // The differing pixels, counted here from the two images, are the figure and the red pixels of the difference image.
        var (render, reference, difference) = (run.Render.Image, run.Reference.Image, ImageReader.Read(settings.Files[2]));
        var differing = 0;
        for (var y = 0; y < render.Height; y++)
            for (var x = 0; x < render.Width; x++)
            {
                var differs = render.GetPixel(x, y) != reference.GetPixel(x, y);
                differing += differs ? 1 : 0;
                Assert.Equal(differs, difference.GetPixel(x, y) == (255, 0, 0));
            }
        Assert.True(differing > 0, "one randomized pass should miss some hits");
        Assert.Equal(differing, run.Figures.Error.DifferentPixels);

        Assert.Equal(16 * 16, run.Figures.Passes[0].Rays);
        Assert.Equal(Counts(run.Reference.Total), Counts(run.Figures.ClassicalReference));
        Assert.Null(run.Figures.ConvergedError);
        Assert.Equal(RunPlace.NoBridges, run.RanOn);
    }

    [Fact]
    public void SameSettingsGiveTheSameBytesAndAnotherSeedOthers()
    {
        var first = RenderRun.Run(Randomized("a.png"));
        var again = RenderRun.Run(Randomized("b.png"));
        var other = RenderRun.Run(Randomized("c.png", seed: 6));

        Assert.Equal(File.ReadAllBytes(_scratch.File("a.png")), File.ReadAllBytes(_scratch.File("b.png")));
        Assert.Equal(Counts(first.Figures.Total), Counts(again.Figures.Total));
        Assert.NotEqual(File.ReadAllBytes(_scratch.File("a.png")), File.ReadAllBytes(_scratch.File("c.png")));
    }

    [Fact]
    public void SampledLightAddsTheConvergedReference()
    {
        var scene = Load("qornell-64-area.json");
        var settings = new RenderRunSettings(scene, RenderDefaults.Options(8, 8) with { AreaSamples = 2 }, new EngineSetup(EngineKind.Analytic),
            _scratch.File("area.png"), WithReference: true, ReferenceSamples: 16);
        var run = RenderRun.Run(settings);

        Assert.Equal(["area-converged.png", "area-difference.png", "area-reference.png", "area.png"], _scratch.FileNames());
        var converged = Assert.IsType<RenderResult>(run.Converged);
        Assert.Equal(converged.Image.Pixels.ToArray(), ImageReader.Read(_scratch.File("area-converged.png")).Pixels.ToArray());
        Assert.Equal(16, run.Figures.ConvergedSamples);
        Assert.Equal(ImageError.Between(run.Render.Image, converged.Image), run.Figures.ConvergedError);
        Assert.Equal(ImageError.Between(run.Reference.Image, converged.Image), run.Figures.ConvergedNoise);
        // Two samples per point against sixteen: the same-sample reference shows Monte Carlo noise.
        Assert.True(run.Figures.ConvergedNoise!.Value.DifferentPixels > 0, "2 area samples should not match 16");
    }

    [Fact]
    public void SearchTooWideForTheSimulatorStopsBeforeAnyFile()
    {
        // The limit is checked before anything is sent: no Node bridge starts.
        var settings = new RenderRunSettings(Qornell8, new RenderOptions(4, 4), new EngineSetup(EngineKind.Gate, new QSearchOptions(), Workers: 1, MaxQubits: 10), _scratch.File("g.png"));
        var error = Assert.Throws<UserError>(() => RenderRun.Run(settings));
        Assert.StartsWith($"{Qornell8.Name}: ", error.Message);
        Assert.Contains("--max-qubits", error.Message);
        Assert.Empty(_scratch.FileNames());
    }
}
